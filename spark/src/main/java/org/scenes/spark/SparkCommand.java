package org.scenes.spark;

import java.io.PrintWriter;
import org.apache.spark.SparkException;
import org.scenes.api.PluginException;
import org.scenes.internal.scene.SceneFileException;
import org.scenes.options.OptionException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Spec;
import picocli.CommandLine;

/** The top-level {@code scenes-spark} command: the project's conversion and sweeps as Spark jobs. */
@Command(name = "scenes-spark", mixinStandardHelpOptions = true, versionProvider = SparkCommand.Version.class,
        description = "Conversion and sweeps of scenes as Apache Spark jobs: the same code and results as the scenes "
                + "commands, spread over the cores of this machine (the default, --master local[*]) or of a "
                + "cluster.",
        subcommands = {CommandLine.HelpCommand.class, ConvertCommand.class, ExperimentCommand.class, TuneCommand.class})
final class SparkCommand implements Runnable {
    @Spec
    CommandLine.Model.CommandSpec spec;

    @Mixin
    SparkOptions options;

    @Override
    public void run() {
        spec.commandLine().usage(spec.commandLine().getOut());
    }

    static CommandLine commandLine() {
        CommandLine commandLine = new CommandLine(new SparkCommand());
        commandLine.setExecutionExceptionHandler(SparkCommand::handleError);
        commandLine.setExitCodeExceptionMapper(e -> CommandLine.ExitCode.SOFTWARE);
        commandLine.setParameterExceptionHandler(SparkCommand::handleUsageError);
        return commandLine;
    }

    /** Runs a command line with the given output streams and returns its exit code, for tests. */
    static int run(PrintWriter out, PrintWriter err, String... args) {
        CommandLine commandLine = commandLine();
        commandLine.setOut(out);
        commandLine.setErr(err);
        try {
            return commandLine.execute(args);
        } finally {
            out.flush();
            err.flush();
        }
    }

    private static int handleUsageError(CommandLine.ParameterException e, String[] args) {
        PrintWriter err = e.getCommandLine().getErr();
        err.println("scenes-spark: " + e.getMessage());
        CommandLine.UnmatchedArgumentException.printSuggestions(e, err);
        err.println("Try '" + e.getCommandLine().getCommandSpec().qualifiedName() + " --help' for usage.");
        return CommandLine.ExitCode.USAGE;
    }

    private static int handleError(Exception e, CommandLine commandLine, CommandLine.ParseResult parseResult) {
        PrintWriter err = commandLine.getErr();
        // a task's failure reaches the driver wrapped in Spark's job failure: report the task's own error
        Throwable cause = e;
        while (cause instanceof SparkException && cause.getCause() != null) {
            cause = cause.getCause();
        }
        err.println("scenes-spark: " + message(cause));
        boolean verbose = false;
        for (CommandLine.ParseResult r = parseResult; r != null; r = r.subcommand()) {
            verbose |= r.hasMatchedOption("--verbose");
        }
        if (verbose) {
            e.printStackTrace(err);
        }
        err.flush();
        if (cause instanceof UsageException || cause instanceof PluginException || cause instanceof OptionException
                || cause.getClass() == IllegalArgumentException.class) {
            return CommandLine.ExitCode.USAGE;
        }
        return CommandLine.ExitCode.SOFTWARE;
    }

    private static String message(Throwable e) {
        if (e instanceof SceneFileException || e instanceof UsageException || e instanceof PluginException) {
            return e.getMessage();
        }
        String message = e.getMessage();
        return message == null ? e.getClass().getSimpleName() : message.lines().findFirst().orElse(message);
    }

    static final class Version implements CommandLine.IVersionProvider {
        @Override
        public String[] getVersion() {
            String version = SparkCommand.class.getPackage().getImplementationVersion();
            return new String[] {"scenes-spark " + (version == null ? "(development build)" : version),
                    "Spark " + org.apache.spark.package$.MODULE$.SPARK_VERSION(),
                    "Java " + System.getProperty("java.version") + " (" + System.getProperty("java.vendor") + ")"};
        }
    }
}
