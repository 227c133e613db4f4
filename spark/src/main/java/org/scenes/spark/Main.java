package org.scenes.spark;

/** Entry point of the {@code scenes-spark} launcher. */
public final class Main {
    private Main() {
    }

    public static void main(String[] args) {
        System.exit(SparkCommand.commandLine().execute(args));
    }
}
