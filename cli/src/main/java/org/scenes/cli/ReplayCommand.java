package org.scenes.cli;

import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.scenes.evaluate.ReplayPage;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.GameLogReader;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code scenes replay}: a game log as a web page that replays it. */
@Command(name = "replay", mixinStandardHelpOptions = true,
        description = {"Write a self-contained web page replaying a game log (.rcg, ours or rcssserver's; gzip or"
                + " not): pitch, players, ball, score and play mode, a cycle slider and play/pause."})
final class ReplayCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(paramLabel = "GAME.rcg", description = "The game log.")
    Path game;

    @Option(names = {"-o", "--output"}, paramLabel = "PAGE.html", required = true, description = "The page to write.")
    Path output;

    @Override
    public Integer call() throws Exception {
        OutputPaths.checkFile("-o", output, List.of(game));
        List<GameFrame> frames = GameLogReader.readAll(game);
        if (frames.isEmpty()) {
            throw new UsageException(game + ": no frames (show lines) in this game log");
        }
        GameFrame last = frames.get(frames.size() - 1);
        String title = String.format(Locale.ROOT, "%s %d : %d %s", last.leftTeam(), last.scoreLeft(), last.scoreRight(),
                last.rightTeam());
        ReplayPage.write(output, title + " (" + game.getFileName() + ")", frames);
        spec.commandLine().getOut().printf(Locale.ROOT, "%-14s %s, %d frames, last cycle %d%n%-14s %s%n", "Game", title,
                frames.size(), last.time(), "Written", output.toAbsolutePath());
        return ExitCodes.OK;
    }
}
