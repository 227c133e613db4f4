package org.scenes.cli;

import picocli.CommandLine;

/** Entry point of the {@code scenes} launcher. */
public final class Main {
    private Main() {
    }

    public static void main(String[] args) {
        System.exit(ScenesCommand.commandLine().execute(args));
    }
}
