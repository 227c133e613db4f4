package org.scenes.cli;

import java.io.IOException;
import java.io.InputStream;
import java.io.PrintWriter;
import java.nio.file.FileSystemException;
import java.util.Properties;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.scenes.api.Grid;
import org.scenes.api.PluginException;
import org.scenes.api.PluginRegistry;
import org.scenes.app.RequestException;
import org.scenes.internal.files.IoErrors;
import org.scenes.internal.scene.SceneFileException;
import org.scenes.options.OptionException;
import picocli.CommandLine.Command;
import picocli.CommandLine.IVersionProvider;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Spec;
import picocli.CommandLine;

/** The top-level {@code scenes} command; subcommands do the work. */
@Command(name = "scenes", mixinStandardHelpOptions = true, versionProvider = ScenesCommand.Version.class,
        description = "Learn to play RoboCup 2D soccer by watching another agent: record, convert, validate, play.",
        subcommands = {CommandLine.HelpCommand.class, PluginsCommand.class, ConvertCommand.class,
                ShowCommand.class, StatsCommand.class, ExportCommand.class, CondenseCommand.class,
                ValidateCommand.class, TuneCommand.class, ExperimentCommand.class, BenchCommand.class,
                SimulateCommand.class, PlayCommand.class, TeamCommand.class, EvaluateCommand.class,
                MatchCommand.class, ReplayCommand.class, DemoCommand.class, ProxyCommand.class, ServerCommand.class,
                CompareCommand.class, WorldErrorCommand.class, GameLogCheckCommand.class})
final class ScenesCommand implements Runnable {
    @Spec
    CommandLine.Model.CommandSpec spec;

    @Mixin
    GlobalOptions global;

    @Override
    public void run() {
        spec.commandLine().usage(spec.commandLine().getOut());
    }

    /** A fully wired command line, as {@code main} runs it and tests drive it. */
    static CommandLine commandLine() {
        CommandLine commandLine = new CommandLine(new ScenesCommand());
        commandLine.setExecutionExceptionHandler(ScenesCommand::handleError);
        commandLine.setExitCodeExceptionMapper(e -> ExitCodes.FAILURE);
        commandLine.setParameterExceptionHandler(ScenesCommand::handleUsageError);
        // `--train a --frobnicate b`: an unknown option is a usage error wherever it stands, never a file name
        commandLine.setUnmatchedOptionsAllowedAsOptionParameters(false);
        return commandLine;
    }

    /** picocli's words for a value that starts with '-', such as {@code --bounds=-1,5}. */
    private static final Pattern DASHED_VALUE =
            Pattern.compile("Expected parameter for option '([^']+)' but found '(-[0-9.][^']*)'");

    private static int handleUsageError(CommandLine.ParameterException e, String[] args) {
        PrintWriter err = e.getCommandLine().getErr();
        Matcher dashed = DASHED_VALUE.matcher(e.getMessage());
        if (dashed.find()) {
            // --bounds=-1,5: not an unknown option, a value that looks like one
            err.println("scenes: option '" + dashed.group(1) + "' expects a value, not '" + dashed.group(2)
                    + "' (a word starting with '-' is taken for an option)");
        } else {
            err.println("scenes: " + printable(e.getMessage()));
        }
        CommandLine.UnmatchedArgumentException.printSuggestions(e, err);
        err.println("Try '" + e.getCommandLine().getCommandSpec().qualifiedName() + " --help' for usage.");
        return ExitCodes.USAGE;
    }

    private static int handleError(Exception e, CommandLine commandLine, CommandLine.ParseResult parseResult) {
        PrintWriter err = commandLine.getErr();
        boolean verbose = parseResult.hasMatchedOption("--verbose")
                || (parseResult.subcommand() != null && anyVerbose(parseResult));
        if (Limits.outOfMemory(e) != null) {
            // a worker thread's OutOfMemoryError, wrapped: the same one line as the main thread's
            err.println("scenes: " + Limits.outOfMemoryMessage());
            err.flush();
            return ExitCodes.FAILURE;
        }
        err.println("scenes: " + printable(message(e)));
        if (verbose) {
            e.printStackTrace(err);
        }
        err.flush();
        // usage is typed (a bad option is a UsageException, the options module's OptionException or a service's
        // RequestException); any other failure, an IllegalArgumentException from core about the data included, is
        // failed work
        if (e instanceof UsageException || e instanceof OptionException || e instanceof RequestException
                || e instanceof PluginException) {
            return ExitCodes.USAGE;
        }
        return ExitCodes.FAILURE;
    }

    private static boolean anyVerbose(CommandLine.ParseResult result) {
        for (CommandLine.ParseResult r = result; r != null; r = r.subcommand()) {
            if (r.hasMatchedOption("--verbose")) {
                return true;
            }
        }
        return false;
    }

    /** The one line of a failure, without the {@code scenes:} prefix. */
    static String message(Throwable e) {
        if (e instanceof Grid.MismatchException) {
            // core names no flags; these are the ones that set a grid
            return e.getMessage() + "; convert them with the same --grid and --bounds";
        }
        String directories = "(" + PluginRegistry.PLUGIN_PATH_VARIABLE + ").";
        if (e instanceof PluginException && e.getMessage().endsWith(directories)) {
            // an unknown plugin: the registry names the variable, the command line adds its option
            return e.getMessage().replace(directories, "(--plugin-path DIR or " + PluginRegistry.PLUGIN_PATH_VARIABLE + ").");
        }
        if (e instanceof SceneFileException || e instanceof UsageException || e instanceof PluginException) {
            return e.getMessage();
        }
        if (e instanceof FileSystemException fileSystem && fileSystem.getFile() != null) {
            // java.nio's message is the file's name alone for a denied access: say why as well
            return fileSystem.getFile() + ": " + IoErrors.reason(fileSystem);
        }
        String message = e.getMessage();
        return message == null ? e.getClass().getSimpleName() : message;
    }

    /**
     * Control characters of a message (quoted from a file, or in a file's name) escaped, so they
     * cannot drive the terminal, and a newline cannot break the message's one line.
     */
    static String printable(String message) {
        StringBuilder text = new StringBuilder(message.length());
        for (int i = 0; i < message.length(); i++) {
            char c = message.charAt(i);
            if (c < 0x20 || c == 0x7f) {
                text.append(String.format("\\x%02X", (int) c));
            } else {
                text.append(c);
            }
        }
        return text.toString();
    }

    /**
     * Version and git commit as the build wrote them (build-info.properties, a resource made by
     * cli's buildInfo task), so they never drift from the build; "unknown" where the build had no git.
     */
    static final class Version implements IVersionProvider {
        @Override
        public String[] getVersion() throws IOException {
            Properties info = new Properties();
            try (InputStream in = ScenesCommand.class.getResourceAsStream("build-info.properties")) {
                if (in != null) {
                    info.load(in);
                }
            }
            return new String[] {"scenes " + info.getProperty("version", "(development build)")
                    + ", commit " + info.getProperty("commit", "unknown"),
                    "Java " + System.getProperty("java.version") + " (" + System.getProperty("java.vendor") + ")"};
        }
    }
}
