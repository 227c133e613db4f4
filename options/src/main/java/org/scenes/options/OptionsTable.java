package org.scenes.options;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import picocli.CommandLine;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.Model.PositionalParamSpec;

/**
 * Every option of a command line and its subcommands as Markdown tables, read from picocli's model
 * (names, value, default, description), so the table in docs cannot drift from the options: a test
 * compares the file with this text.
 */
public final class OptionsTable {
    private OptionsTable() {
    }

    /**
     * The tables of {@code root}'s options (those every subcommand inherits, listed once) and of its
     * subcommands' own (and their subcommands'), one section each, in declaration order. Defaults are
     * the declared ones; where a default depends on the machine (the number of cores) the description
     * says so.
     */
    public static String markdown(CommandLine root) {
        StringBuilder text = new StringBuilder();
        table(text, root.getCommandSpec());
        for (Map.Entry<String, CommandLine> entry : root.getSubcommands().entrySet()) {
            CommandSpec spec = entry.getValue().getCommandSpec();
            if (!entry.getKey().equals(spec.name()) || spec.userObject() instanceof CommandLine.HelpCommand) {
                continue; // an alias, or `help`
            }
            section(text, entry.getValue());
        }
        return text.toString();
    }

    private static void section(StringBuilder text, CommandLine command) {
        table(text, command.getCommandSpec());
        for (CommandLine sub : command.getSubcommands().values()) {
            section(text, sub);
        }
    }

    private static void table(StringBuilder text, CommandSpec spec) {
        List<OptionSpec> options = new ArrayList<>();
        for (OptionSpec option : spec.options()) {
            if (!option.usageHelp() && !option.versionHelp() && !option.hidden() && !option.inherited()) {
                options.add(option);
            }
        }
        text.append("## ").append(spec.qualifiedName()).append(spec.parent() == null ? " (every command)" : "")
                .append("\n\n");
        if (options.isEmpty() && spec.positionalParameters().isEmpty()) {
            text.append("No options.\n\n");
        } else {
            text.append("| option | value | default | description |\n| --- | --- | --- | --- |\n");
            for (OptionSpec option : options) {
                text.append("| ").append(cell(String.join(", ", option.names())))
                        .append(" | ").append(cell(option.typeInfo().isBoolean() ? "" : option.paramLabel()))
                        .append(" | ").append(cell(option.defaultValue() == null ? "" : option.defaultValue()))
                        .append(" | ").append(cell(String.join(" ", option.description())))
                        .append(option.required() && option.group() == null ? " (required)" : "")
                        .append(" |\n");
            }
            for (PositionalParamSpec parameter : spec.positionalParameters()) {
                text.append("| (arguments) | ").append(cell(parameter.paramLabel())).append(" | ")
                        .append(cell(parameter.defaultValue() == null ? "" : parameter.defaultValue())).append(" | ")
                        .append(cell(String.join(" ", parameter.description()))).append(" |\n");
            }
            text.append('\n');
        }
    }

    private static String cell(String text) {
        return text.replaceAll("\\s+", " ").trim().replace("|", "\\|").replace("<", "&lt;");
    }
}
