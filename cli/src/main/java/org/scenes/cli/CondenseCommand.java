package org.scenes.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.scenes.app.condense.Condensation;
import org.scenes.internal.validate.MatchConfig;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;

/** {@code scenes condense}: a smaller knowledge base that predicts the dropped scenes as the whole one did. */
@Command(name = "condense", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Keep only the scenes that decide something: edited (Wilson) then condensed (Hart) nearest neighbour",
                "with the configuration's metric; writes one scene file usable wherever scene files are (docs/extensions.md)."})
final class CondenseCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @ParentCommand
    ScenesCommand top;

    @Option(names = "--train", arity = "1..*", paramLabel = "FILE", required = true, description = "Scene files to condense.")
    List<Path> train = new ArrayList<>();

    @Option(names = {"-o", "--output"}, paramLabel = "OUT.json[.gz]", required = true, description = "The condensed scene file.")
    Path output;

    @Option(names = "--edit-k", paramLabel = "K",
            description = "Neighbours whose majority must agree with a scene for editing to keep it (default 3; 0: no editing).")
    int editK = 3;

    @Mixin
    MatchOptions match;

    @Override
    public Integer call() throws Exception {
        OutputPaths.checkFile("-o", output, train);
        if (editK < 0) {
            throw new UsageException("--edit-k must be 0 or more, not " + editK);
        }
        List<MatchConfig> configs = match.configs();
        if (configs.size() != 1) {
            throw new UsageException("condense takes one metric and one k");
        }
        MatchConfig config = configs.get(0);
        Condensation.Result result = Condensation.run(new Condensation.Request(train, config, editK, output),
                top.global.registry());
        PrintWriter out = spec.commandLine().getOut();
        out.printf(Locale.ROOT, "%-24s %s%n", "Configuration", config.describe());
        out.printf(Locale.ROOT, "%-24s %d%n", "Scenes", result.scenes());
        out.printf(Locale.ROOT, "%-24s %d%n", "Edited away", result.edited());
        out.printf(Locale.ROOT, "%-24s %d (%.1f %% of the scenes), %d passes%n", "Kept", result.kept(),
                100.0 * result.kept() / result.scenes(), result.passes());
        out.printf(Locale.ROOT, "%-24s %.1f s%n", "Time", result.seconds());
        out.printf(Locale.ROOT, "%-24s %s%n", "Written", output);
        return ExitCodes.OK;
    }
}
