package org.scenes.evaluate;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Objects;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import org.scenes.simulator.Brain;
import org.scenes.simulator.BrainFactory;

/**
 * A team that is not ours: a command started for each game ({@code bash -c}, in a session of its
 * own so that the whole process group can be ended), its players connecting to the server by
 * themselves. The command is a template: {@code {host}}, {@code {port}}, {@code {team}} and
 * {@code {players}} are replaced by the server's address, the team name and its number of players.
 * It stands where a team's brains stand ({@link org.scenes.simulator.GameSetup.Team#brains()}),
 * but only a live server ({@link LiveArena}) can play it: it makes no brain in process.
 */
public record ExternalTeam(String command) implements BrainFactory {
    /** How long the group has to end after SIGTERM before it is killed. */
    private static final long TERM_MILLIS = 2000;

    public ExternalTeam {
        Objects.requireNonNull(command, "command");
        if (command.isBlank()) {
            throw new IllegalArgumentException("an empty command");
        }
    }

    @Override
    public Brain create(String team, Random random) {
        throw new UnsupportedOperationException("the command '" + command + "' plays only on a server (--server)");
    }

    /** The command with its placeholders replaced. */
    public String expand(String host, int port, String team, int players) {
        return command.replace("{host}", host).replace("{port}", Integer.toString(port)).replace("{team}", team)
                .replace("{players}", Integer.toString(players));
    }

    /** Starts the command in a new session; its output goes to {@code output}. */
    public Running start(String host, int port, String team, int players, Path output) throws IOException {
        return launch(expand(host, port, team, players), output);
    }

    /** Starts an expanded command in a new session; its output goes to {@code output}. */
    static Running launch(String expanded, Path output) throws IOException {
        ProcessBuilder builder = new ProcessBuilder("setsid", "bash", "-c", expanded).redirectErrorStream(true)
                .redirectOutput(output.toFile());
        Process process;
        try {
            process = builder.start();
        } catch (IOException e) {
            throw new IOException("could not start '" + expanded + "': " + e.getMessage());
        }
        // setsid runs bash in its own place (its parent is no group leader): its pid is the group's
        return new Running(expanded, process, process.pid(), output);
    }

    /** A started command: its process group and where its output went. */
    public static final class Running implements AutoCloseable {
        private final String command;
        private final Process process;
        private final long group;
        private final Path output;

        Running(String command, Process process, long group, Path output) {
            this.command = command;
            this.process = process;
            this.group = group;
            this.output = output;
        }

        public String command() {
            return command;
        }

        /** Whether any process of the group is left (the command's own shell may have ended). */
        public boolean alive() {
            return process.isAlive() || signal("0");
        }

        /** The exit code of the command's shell, or null while it runs. */
        public Integer exitCode() {
            return process.isAlive() ? null : process.exitValue();
        }

        /** The last line the command printed, for a message; empty when none. */
        public String lastWords() {
            try {
                List<String> lines = Files.readAllLines(output, StandardCharsets.UTF_8);
                for (int i = lines.size() - 1; i >= 0; i--) {
                    if (!lines.get(i).isBlank()) {
                        String line = lines.get(i).strip();
                        return line.length() > 160 ? line.substring(0, 160) + "..." : line;
                    }
                }
            } catch (IOException | UncheckedIOException e) {
                // no output to quote
            }
            return "";
        }

        /** Ends the whole group: SIGTERM, then SIGKILL for what is left after a moment. */
        @Override
        public void close() {
            signal("TERM");
            long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(TERM_MILLIS);
            while (alive() && System.nanoTime() < deadline) {
                try {
                    Thread.sleep(50);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    break;
                }
            }
            if (alive()) {
                signal("KILL");
                try {
                    process.waitFor(1, TimeUnit.SECONDS);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        }

        /** Sends a signal to the group with kill(1); true when some process of it got it. */
        private boolean signal(String name) {
            try {
                Process kill = new ProcessBuilder("kill", "-" + name, "--", "-" + group)
                        .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
                return kill.waitFor() == 0;
            } catch (IOException e) {
                return false;
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return false;
            }
        }
    }
}
