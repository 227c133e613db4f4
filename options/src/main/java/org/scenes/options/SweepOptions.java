package org.scenes.options;

import java.nio.file.Path;
import org.scenes.internal.experiment.Sweep;
import org.scenes.plugins.script.ScriptFailure;
import org.scenes.plugins.script.Sweeps;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code experiment SWEEP.groovy [--out-dir DIR] [--name NAME]}: the sweep script and where its table goes. */
public final class SweepOptions {
    @Parameters(paramLabel = "SWEEP.groovy", description = "The sweep script (docs/scripting.md).")
    private Path sweepFile;

    @Option(names = {"-o", "--out-dir"}, paramLabel = "DIR",
            description = "Where NAME.csv, NAME.json, NAME.md (and for 'scenes experiment' NAME.svg) go; for"
                    + " scenes-spark any Hadoop-compatible path (default: the sweep script's directory).")
    private String outDir;

    @Option(names = "--name", paramLabel = "NAME", description = "Base name of the result files (default: the script's name).")
    private String name;

    public Path sweepFile() {
        return sweepFile;
    }

    /** The result files' base name: --name, or the script's name without {@code .groovy}. */
    public String baseName() {
        return name != null ? name : sweepFile.getFileName().toString().replaceFirst("\\.groovy$", "");
    }

    /** --out-dir, or the script's directory. */
    public String outDir() {
        return outDir != null ? outDir : sweepFile.toAbsolutePath().getParent().toString();
    }

    /** The command line as given, for the result table's JSON. */
    public String command(String program) {
        return program + " experiment " + sweepFile + (outDir == null ? "" : " --out-dir " + outDir)
                + (name == null ? "" : " --name " + name);
    }

    /**
     * The sweep the script describes.
     *
     * @throws OptionException when the script fails: a sweep script describes the run, so
     *                                  its failure is a bad command line, like a bad option
     */
    public Sweep load() {
        try {
            return Sweeps.load(sweepFile.toString());
        } catch (ScriptFailure e) {
            throw new OptionException(e.getMessage(), e);
        }
    }
}
