package org.scenes.cli;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import org.scenes.internal.gamelog.GameLogs;
import org.scenes.internal.inference.CommandCheck;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code scenes gamelog-check}: the commands inferred from game logs alone set against their command logs. */
@Command(name = "gamelog-check", mixinStandardHelpOptions = true,
        description = {"Infer the players' commands from game logs alone (as convert --commands infer does) and"
                + " set them against the command logs beside them (GAME.rcl): per executed body command, whether"
                + " the type agrees, and the errors of turn moments, dash powers and kick directions."})
final class GameLogCheckCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(paramLabel = "GAME.rcg", arity = "1..*", description = "Game logs, each with its command log beside it.")
    List<Path> games = new ArrayList<>();

    @Override
    public Integer call() throws Exception {
        CommandCheck.Result total = null;
        for (Path game : games) {
            Path commands;
            try {
                commands = GameLogs.commandLogBeside(game);
            } catch (IllegalArgumentException e) {
                throw new UsageException(e.getMessage());
            }
            CommandCheck.Result result = CommandCheck.check(game, commands);
            total = total == null ? result : total.add(result);
        }
        for (String warning : total.warnings()) {
            spec.commandLine().getErr().println("scenes: warning: " + warning);
        }
        spec.commandLine().getOut().print(total.table());
        spec.commandLine().getOut().flush();
        return ExitCodes.OK;
    }
}
