package org.scenes.evaluate;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Random;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import org.scenes.internal.protocol.InitReply;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.ProtocolException;
import org.scenes.simulator.Brain;
import org.scenes.simulator.BrainFactory;

/**
 * A shadow teacher that is a program speaking the soccer server's protocol (HELIOS base's
 * player, the classic Krislet, {@code scenes team}): for each imitating player, a process of a
 * command template, started in a session of its own when the server answers the imitator's init.
 * {@code {host}} and {@code {port}} are replaced by the address of a {@link ShadowEndpoint} of its
 * own, {@code {team}} by the team's name, {@code {players}} by 1 and {@code {unum}} by the
 * imitating player's uniform number. Its init is answered with the very answer the server gave
 * the imitator (same side, number and play mode); from then on it is sent every message the
 * imitator receives (parameters, {@code sense_body}, {@code see}, {@code hear}, errors), and each
 * command it sends is recorded ({@link Player#sent}) and handed on as the shadow's, never executed.
 *
 * <p>Which message a command answers ({@link Pacing}): in the embedded simulator, which is
 * synchronous and sends no {@code (think)}, each message is followed by a {@code (think)} and the
 * program's commands up to its {@code (done)} answer that message, as an in-process brain's do. On
 * a live server the server's own {@code (think)} is forwarded and the cycle's commands are those up
 * to the program's {@code (done)}; on a real-time server (no {@code (think)}) a command answers the
 * latest message sent before it came ({@link LateShadow}).
 *
 * <p>A program that fails to start, sends no init, no {@code (done)} in time or ends during the
 * game fails the game with one line naming the player and the command. {@link #endGame} ends the
 * whole process group of every shadow of the game.
 */
public final class ExternalShadow implements BrainFactory {
    /** How the program's commands are matched to the messages they answer. */
    public enum Pacing {
        /** The embedded simulator: a {@code (think)} after each message, its commands up to {@code (done)}. */
        EACH_MESSAGE,
        /** A live server: its {@code (think)} is forwarded in synchronous mode; in real time, commands as they come. */
        AS_THE_SERVER
    }

    /** How long a program may take to send {@code (done)} after a {@code (think)}. */
    private static final Duration DONE_WAIT = Duration.ofSeconds(10);
    private static final long POLL_MILLIS = 100;
    /** In real time, how many {@code sense_body}s pass between looks at whether the program still runs. */
    private static final int HEALTH_EVERY = 20;

    private final String command;
    private final Pacing pacing;
    private final Duration initWait;
    private final List<Player> players = new ArrayList<>();
    /** Programs started by {@link #startGame}, waiting for their players, by uniform number. */
    private final Map<Integer, Program> waiting = new HashMap<>();
    /** The {@code (done)}s the programs sent, over all games. */
    private final AtomicLong dones = new AtomicLong();

    /**
     * @param command the template
     * @param initWait how long a program may take to send its init
     */
    public ExternalShadow(String command, Pacing pacing, Duration initWait) {
        this.command = Objects.requireNonNull(command, "command");
        if (command.isBlank()) {
            throw new IllegalArgumentException("an empty command");
        }
        this.pacing = Objects.requireNonNull(pacing, "pacing");
        this.initWait = Objects.requireNonNull(initWait, "initWait");
    }

    public String command() {
        return command;
    }

    public Pacing pacing() {
        return pacing;
    }

    @Override
    public Brain create(String team, Random random) {
        Player player = new Player(team);
        synchronized (players) {
            players.add(player);
        }
        return player;
    }

    /** The template with its placeholders replaced. */
    String expand(String host, int port, String team, int unum) {
        return command.replace("{host}", host).replace("{port}", Integer.toString(port)).replace("{team}", team)
                .replace("{players}", "1").replace("{unum}", Integer.toString(unum));
    }

    /**
     * Starts the programs of a team of {@code count} players before its game, all at once, and
     * waits until each has sent its init (which is answered when its player's is): a program that
     * starts slowly keeps no player of the game waiting, and none hears nothing for long. Player
     * {@code n}'s program is started with {@code {unum}} n; a player given another number by the
     * server gets a program started then.
     */
    public void startGame(String team, int count) throws IOException {
        List<Program> started = new ArrayList<>();
        try {
            for (int unum = 1; unum <= count; unum++) {
                Program program = Program.launch(this, team, unum);
                started.add(program);
                synchronized (players) {
                    waiting.put(unum, program);
                }
            }
            long deadline = System.nanoTime() + initWait.toNanos();
            for (Program program : started) {
                program.awaitInit(deadline, initWait);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while the shadows of " + team + " started");
        }
    }

    /** Ends the process groups of the game's shadows; the next game starts new ones. */
    public void endGame() {
        List<Player> ending;
        List<Program> unused;
        synchronized (players) {
            ending = List.copyOf(players);
            players.clear();
            unused = List.copyOf(waiting.values());
            waiting.clear();
        }
        ending.forEach(Player::close);
        unused.forEach(Program::close);
    }

    /** The {@code (done)}s the programs sent so far, over all games. */
    long dones() {
        return dones.get();
    }

    /** The shadows of the game under way, in the order they were made. */
    List<Player> players() {
        synchronized (players) {
            return List.copyOf(players);
        }
    }

    /** A command the program sent, and the game time of the latest {@code sense_body} or {@code see} before it. */
    record Sent(int time, String command) {
    }

    /** One started program: its endpoint, its process group and where its output goes. */
    private static final class Program {
        final String name;
        final String command;
        final ShadowEndpoint endpoint;
        final Path output;
        final ExternalTeam.Running running;

        private Program(String name, String command, ShadowEndpoint endpoint, Path output,
                        ExternalTeam.Running running) {
            this.name = name;
            this.command = command;
            this.endpoint = endpoint;
            this.output = output;
            this.running = running;
        }

        /** Starts player {@code unum}'s program on an endpoint of its own. */
        static Program launch(ExternalShadow shadow, String team, int unum) throws IOException {
            ShadowEndpoint endpoint = new ShadowEndpoint();
            Path output = null;
            try {
                output = Files.createTempFile("scenes-shadow-" + team + "-" + unum + "-", ".log");
                String expanded = shadow.expand(endpoint.host(), endpoint.port(), team, unum);
                return new Program(team + " player " + unum + "'s shadow", expanded, endpoint, output,
                        ExternalTeam.launch(expanded, output));
            } catch (IOException | RuntimeException e) {
                endpoint.close();
                if (output != null) {
                    Files.deleteIfExists(output);
                }
                throw e;
            }
        }

        /** Waits until the program sent its init (left unanswered), or fails when it ended or {@code deadline} passed. */
        void awaitInit(long deadline, Duration wait) throws IOException, InterruptedException {
            while (true) {
                String datagram = endpoint.take(POLL_MILLIS);
                if (datagram != null && datagram.startsWith("(init")) {
                    return;
                }
                if (datagram == null && !running.alive()) {
                    throw new IOException(name + ": the command '" + command + "' ended (exit " + running.exitCode()
                            + ") before it sent its init" + quoted());
                }
                if (System.nanoTime() > deadline) {
                    throw new IOException(name + ": the command '" + command + "' sent no init to " + endpoint.host()
                            + ":" + endpoint.port() + " within " + wait.toSeconds() + " s"
                            + quoted());
                }
            }
        }

        String quoted() {
            String words = running.lastWords();
            return words.isEmpty() ? "" : " (it said: " + words + ")";
        }

        void close() {
            running.close();
            endpoint.close();
            try {
                Files.deleteIfExists(output);
            } catch (IOException e) {
                // a temporary file left in the temporary directory
            }
        }
    }

    /** One imitating player's shadow: its program and the record of what it sent. */
    final class Player implements Brain, LateShadow {
        private final String team;
        private final MessageParser parser = new MessageParser();
        private final List<Sent> sent = new ArrayList<>();
        private Program program;
        private int time;
        /** A {@code (think)} came from the server: synchronous mode. */
        private boolean synchronous;
        /** The referee said {@code time_over}: the program may leave; nothing more is waited for. */
        private boolean timeOver;
        private int senses;

        Player(String team) {
            this.team = team;
        }

        @Override
        public void receive(String message, Consumer<String> send) {
            try {
                if (program == null) {
                    start(message);
                    return;
                }
                boolean senseBody = message.startsWith("(sense_body ");
                if (senseBody || message.startsWith("(see ")) {
                    time = timeOf(message);
                }
                if (timeOver) {
                    return;
                }
                timeOver = message.startsWith("(hear ") && message.endsWith(" referee time_over)");
                program.endpoint.send(message);
                if (timeOver) {
                    return;
                }
                if (pacing == Pacing.EACH_MESSAGE) {
                    program.endpoint.send("(think)");
                    awaitDone(send);
                } else if (message.equals("(think)")) {
                    synchronous = true;
                    awaitDone(send);
                } else if (senseBody && ++senses % HEALTH_EVERY == 0 && !program.running.alive()) {
                    throw ended();
                }
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new UncheckedIOException(new IOException(program.name + ": interrupted"));
            }
        }

        @Override
        public void collect(Consumer<String> send) {
            if (program == null || pacing == Pacing.EACH_MESSAGE || synchronous) {
                return; // all handed on at the (done)
            }
            for (String datagram = program.endpoint.poll(); datagram != null; datagram = program.endpoint.poll()) {
                handOn(datagram, send);
            }
        }

        /** Every command the program sent but {@code (done)}, in order. */
        List<Sent> sent() {
            return sent;
        }

        /**
         * On the server's answer to the imitator's init: takes the program started for this
         * number (or starts one) and answers its init alike.
         */
        private void start(String message) throws IOException, InterruptedException {
            InitReply init;
            try {
                if (!(parser.parse(message) instanceof InitReply reply) || reply.side() == null) {
                    return;
                }
                init = reply;
            } catch (ProtocolException e) {
                return;
            }
            synchronized (players) {
                program = waiting.remove(init.uniformNumber());
            }
            if (program == null) {
                program = Program.launch(ExternalShadow.this, team, init.uniformNumber());
                program.awaitInit(System.nanoTime() + initWait.toNanos(), initWait);
            }
            program.endpoint.send(message);
        }

        private void awaitDone(Consumer<String> send) throws IOException, InterruptedException {
            long deadline = System.nanoTime() + DONE_WAIT.toNanos();
            while (true) {
                String datagram = program.endpoint.take(POLL_MILLIS);
                if (datagram != null) {
                    if (handOn(datagram, send)) {
                        return;
                    }
                    continue;
                }
                if (!program.running.alive()) {
                    throw ended();
                }
                if (System.nanoTime() > deadline) {
                    throw new IOException(program.name + ": the command '" + program.command + "' sent no (done)"
                            + " within " + DONE_WAIT.toSeconds() + " s of a (think) at cycle " + time
                            + (pacing == Pacing.EACH_MESSAGE ? " (in the embedded simulator a shadow must answer"
                                    + " (think); shadow a real-time client on a real-time server, --server)" : "")
                            + program.quoted());
                }
            }
        }

        /** Records and hands on the commands of one datagram; true when it held {@code (done)}. */
        private boolean handOn(String datagram, Consumer<String> send) {
            boolean done = false;
            for (String text : parser.texts(datagram)) {
                if (text.startsWith("(done")) {
                    done = true;
                    dones.incrementAndGet();
                } else {
                    sent.add(new Sent(time, text));
                    send.accept(text);
                }
            }
            return done;
        }

        private IOException ended() {
            return new IOException(program.name + ": the command '" + program.command + "' ended (exit "
                    + program.running.exitCode() + ") at cycle " + time + ", before time over" + program.quoted());
        }

        private void close() {
            if (program != null) {
                program.close();
            }
        }
    }

    /** The integer after a message's head word ({@code (see 42 ...)}: 42); 0 when there is none. */
    private static int timeOf(String message) {
        int i = message.indexOf(' ') + 1;
        int value = 0;
        for (int digits = 0; i > 0 && i < message.length() && Character.isDigit(message.charAt(i)) && digits < 9;
             i++, digits++) {
            value = value * 10 + (message.charAt(i) - '0');
        }
        return value;
    }
}
