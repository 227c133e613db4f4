package org.scenes.cli;

import java.io.PrintWriter;
import java.util.Map;
import java.util.concurrent.Callable;
import org.scenes.api.PluginInfo;
import org.scenes.api.PluginKind;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;

/** {@code scenes plugins}: every metric, selector and transform with its description and jar. */
@Command(name = "plugins", mixinStandardHelpOptions = true,
        description = "List every metric, selector and scene transform, with description, options and origin jar.")
final class PluginsCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @ParentCommand
    ScenesCommand top;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        PluginKind current = null;
        for (PluginInfo info : top.global.registry().list()) {
            if (info.kind() != current) {
                current = info.kind();
                out.printf("%s%ss:%n", current == PluginKind.METRIC ? "" : "\n",
                        Character.toUpperCase(current.label().charAt(0)) + current.label().substring(1));
            }
            out.printf("  %-14s %s  [%s]%n", info.name(), info.description(), info.origin());
            for (Map.Entry<String, String> option : info.options().entrySet()) {
                out.printf("  %-14s   %s %s=...  %s%n", "", optionFlag(info.kind()), option.getKey(), option.getValue());
            }
        }
        out.flush();
        return ExitCodes.OK;
    }

    /** How an option of this kind of plugin is given on the command line (MatchOptions). */
    private static String optionFlag(PluginKind kind) {
        return switch (kind) {
            case METRIC -> "--option";
            case SELECTOR -> "--selector-option";
            case TRANSFORM -> "option"; // transforms take their defaults: no command-line flag yet
        };
    }
}
