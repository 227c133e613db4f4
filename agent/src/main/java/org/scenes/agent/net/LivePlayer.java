package org.scenes.agent.net;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.TreeMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.scenes.agent.net.Connection.Datagram;
import org.scenes.agent.net.PlayerReport.Outcome;
import org.scenes.internal.protocol.Hear;
import org.scenes.internal.protocol.InitReply;
import org.scenes.internal.protocol.Message;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.Parameters;
import org.scenes.internal.protocol.ProtocolException;
import org.scenes.internal.protocol.See;
import org.scenes.internal.protocol.SenseBody;
import org.scenes.internal.protocol.ServerNotice;
import org.scenes.simulator.Brain;

/**
 * One player on a real (or fake) soccer server: its socket, its brain, its health.
 *
 * <p>Every datagram is parsed once with core's {@link MessageParser}; one the parser refuses is
 * counted by head, logged once per head and not given to the brain. Everything else goes to the
 * brain as text, in arrival order, and what the brain answers goes out at once, one datagram per
 * command. A {@code (think)} (synchronous mode) is answered with {@code (done)} after the brain
 * has acted on everything before it.
 *
 * <p><b>Cycles, due and missed.</b> A cycle is the time from one {@code sense_body} to the next
 * (the server sends one per cycle); cycles played counts them. A body command ({@code dash},
 * {@code turn}, {@code kick}, {@code move}, {@code catch}, {@code tackle}) is <em>due</em> in a
 * cycle when the brain answers a message of that cycle with one; brains that choose to wait (the
 * classic Krislet acts every second cycle) owe nothing in the cycles they skip. A due cycle is
 * <em>missed</em> when its command left too late for the server to execute it in that cycle.
 * Just before sending, the player takes in everything its socket holds; the command is late when
 * a {@code sense_body} of a later cycle is among it: one stamped with a later time than the
 * message answered, or, for an answer to a {@code sense_body}, any. (The server may send a
 * cycle's {@code see} just before that cycle's own {@code sense_body}; while the clock stands
 * still, before kick-off and after goals, all carry the same time, so a {@code see}'s answer is
 * late when two {@code sense_body}s of its time are waiting.) That is real-time mode. In
 * synchronous mode (a {@code (think)} has come, or {@code server_param} said {@code synch_mode 1})
 * a cycle ends with this player's {@code (done)}: the server executes everything that came before
 * it, and steps only when every player is done. This player answers a {@code (think)} only after
 * acting on everything before it, so no synchronous cycle is missed; a {@code see} the server
 * sends after its {@code (think)} (version 17 and older: the view does not keep to the cycle)
 * is answered in the next cycle, as intended. There the figure that counts is the decision time:
 * how long the server waits.
 * The decision-time sample is the brain's answers that held a body command: its mean and 99th
 * percentile describe the same calls.
 *
 * <p><b>Kick-off positions.</b> The brain's own {@code move} before kick-off is remembered. The
 * real server puts only players in the wrong half back after a goal, so after the
 * referee's {@code goal_*}, and after {@code half_time}, the player sends that move again at the
 * start of the next two cycles: the server executes the first body command of a cycle, and a
 * cycle's {@code see} may come before its {@code sense_body}. A brain that never moved gets a
 * formation spot by uniform number at the first {@code sense_body}.
 */
public final class LivePlayer implements Runnable {
    /** How long one wait on the socket lasts before the stop flag is looked at again. */
    private static final long POLL_MILLIS = 100;
    /** The init is sent again this often until the server answers or the connect timeout ends. */
    static final long HELLO_AGAIN_MILLIS = 1000;
    /** Own-half spots by uniform number, for brains that do not move themselves. */
    private static final double[][] FORMATION = {
        {-50, 0}, {-40, -20}, {-40, -7}, {-40, 7}, {-40, 20}, {-25, -20},
        {-25, -7}, {-25, 7}, {-25, 20}, {-10, -8}, {-10, 8}};

    private final ClientOptions options;
    private final Brain brain;
    private final boolean goalie;
    private final Consumer<String> notices;
    private final CountDownLatch answered = new CountDownLatch(1);
    private final MessageParser parser = new MessageParser();
    private final ArrayDeque<Datagram> queue = new ArrayDeque<>();
    private final List<String> pending = new ArrayList<>(4);
    private final DecisionTimes times = new DecisionTimes();
    private final Map<String, Long> errors = new TreeMap<>();
    private final Map<String, Long> malformed = new TreeMap<>();
    private volatile boolean stopRequested;
    private volatile Connection connection;
    private volatile PlayerReport report;
    private volatile int unum;
    private volatile String side = "";

    private Connection link;
    private TrafficLog log;
    private long cycles;
    /** When the last message that parsed arrived. */
    private long lastUnderstood;
    /**
     * When the last datagram was taken from the socket, however it was taken: those that came
     * while the brain was thinking are taken in after its answer and count as heard too.
     */
    private long lastHeard;
    private long due;
    private long missed;
    private long thinks;
    private long commands;
    private long dueCycle = -1;
    private long missedCycle = -1;
    private String kickOffMove;
    /** Kick-off moves still to send, one per cycle start. */
    private int movesOwed;
    private boolean gameOver;
    private boolean synchronous;
    /** The latest time a timed message (see, sense_body, hear) carried. */
    private int lastTime;

    /**
     * @param goalie whether this player inits as goalie
     * @param notices one-line messages for the user (a malformed message, a failure), from this
     *                player's thread
     */
    public LivePlayer(ClientOptions options, Brain brain, boolean goalie, Consumer<String> notices) {
        this.options = Objects.requireNonNull(options, "options");
        this.brain = Objects.requireNonNull(brain, "brain");
        this.goalie = goalie;
        this.notices = Objects.requireNonNull(notices, "notices");
    }

    @Override
    public void run() {
        PlayerReport result;
        try {
            result = play();
        } catch (RuntimeException | Error e) {
            // a dead player says so; it never takes the team down silently
            result = report(Outcome.FAILED, "failed: " + e);
            notices.accept(name() + " " + result.reason());
        } finally {
            answered.countDown();
        }
        report = result;
    }

    /** Asks the player to send {@code (bye)} and stop; returns at once. */
    public void stop() {
        stopRequested = true;
        Connection current = connection;
        if (current != null) {
            current.wakeup();
        }
    }

    /** Waits until the server answered the init, or the player gave up; true when it answered. */
    public boolean awaitAnswer(long timeout, TimeUnit unit) throws InterruptedException {
        return answered.await(timeout, unit) && unum > 0;
    }

    /** The report once the player has stopped, else null. */
    public PlayerReport report() {
        return report;
    }

    /** {@code TEAM UNUM} as the user knows the player. */
    public String name() {
        return options.team() + " " + (unum > 0 ? "player " + unum : "(not connected)");
    }

    private PlayerReport play() {
        try (Connection opened = new Connection(options.server())) {
            link = opened;
            connection = opened;
            try {
                return session();
            } finally {
                closeLog();
            }
        } catch (IOException e) {
            return fail(unum > 0 ? Outcome.SERVER_LOST : Outcome.NO_SERVER, "network failure: " + e.getMessage());
        }
    }

    private PlayerReport session() throws IOException {
        String hello = options.hello(goalie);
        Datagram reply = null;
        long deadline = System.nanoTime() + options.connectTimeout().toNanos();
        long nextHello = System.nanoTime();
        while (reply == null && !stopRequested && System.nanoTime() < deadline) {
            if (System.nanoTime() - nextHello >= 0) {
                // a server (or proxy) started a moment after the team never saw the first init: say it again
                link.sendHello(hello);
                nextHello = System.nanoTime() + HELLO_AGAIN_MILLIS * 1_000_000;
            }
            long until = Math.min(deadline, nextHello) - System.nanoTime();
            reply = link.awaitReply(Math.max(1, Math.min(POLL_MILLIS * 1_000_000, until)));
        }
        if (reply == null) {
            return stopRequested ? report(Outcome.STOPPED, "stopped before the server answered")
                    : fail(Outcome.NO_SERVER, "no answer from a soccer server at " + options.server() + " to "
                            + hello + " within " + seconds(options.connectTimeout().toMillis()) + " s");
        }
        Message first = parseQuietly(reply);
        if (!(first instanceof InitReply init) || init.side() == null) {
            return fail(Outcome.NO_SERVER, "the server at " + options.server() + " refused " + hello + ": "
                    + reply.text());
        }
        side = String.valueOf(init.side().letter());
        unum = init.uniformNumber() > 0 ? init.uniformNumber() : options.reconnect();
        if (options.logDirectory() != null) {
            log = new TrafficLog(options.logDirectory().resolve(options.team() + "_" + unum + ".log"));
            log.sent(hello);
        }
        answered.countDown();
        queue.add(reply);
        lastHeard = reply.receivedNanos();
        lastUnderstood = lastHeard;
        long silence = options.silenceTimeout().toNanos();
        while (!gameOver) {
            while (!queue.isEmpty() && !gameOver) {
                handle(queue.poll());
            }
            if (gameOver) {
                break;
            }
            if (stopRequested) {
                bye();
                return report(Outcome.STOPPED, "");
            }
            // A server that only sends what cannot be parsed is as good as gone: the game cannot go on.
            if (System.nanoTime() - lastUnderstood > silence && System.nanoTime() - lastHeard <= silence) {
                return fail(Outcome.SERVER_LOST, "no message from the server could be parsed for "
                        + seconds(options.silenceTimeout().toMillis()) + " s (" + malformedCount()
                        + " malformed): it is not a soccer server, or a broken one");
            }
            Datagram next = link.await(POLL_MILLIS);
            if (next == null) {
                if (System.nanoTime() - lastHeard > silence) {
                    return fail(Outcome.SERVER_LOST, "no message from the server for "
                            + seconds(options.silenceTimeout().toMillis()) + " s: the server is gone (or a proxy between dropped this player)");
                }
                continue;
            }
            heard(next);
            takeWaiting();
        }
        bye();
        return report(Outcome.GAME_OVER, "");
    }

    private void handle(Datagram datagram) throws IOException {
        if (log != null) {
            log.received(datagram.bytes());
        }
        Message message;
        try {
            message = parser.parse(datagram.bytes(), 0, datagram.bytes().length);
        } catch (ProtocolException e) {
            malformed(datagram, e);
            return;
        }
        lastUnderstood = datagram.receivedNanos();
        boolean think = false;
        boolean cycleStart = false;
        if (message instanceof SenseBody body) {
            cycles++;
            cycleStart = true;
            lastTime = body.time();
        } else if (message instanceof See see) {
            lastTime = see.time();
        } else if (message instanceof ServerNotice notice) {
            if (notice.isError()) {
                errors.merge(notice.text(), 1L, Long::sum);
            }
            think = notice.head().equals("think");
            synchronous |= think;
        } else if (message instanceof Hear hear) {
            lastTime = hear.time();
            if (hear.speaker() == Hear.Speaker.REFEREE) {
                referee(hear.text());
            }
        } else if (message instanceof Parameters parameters && parameters.head().equals("server_param")) {
            synchronous |= parameters.number("synch_mode") == 1;
        }
        if (cycleStart) {
            positionIfNeeded();
        }
        pending.clear();
        long started = System.nanoTime();
        brain.receive(datagram.text(), pending::add);
        long took = System.nanoTime() - started;
        if (!pending.isEmpty()) {
            boolean body = false;
            for (String command : pending) {
                body |= isBody(command);
                if (command.startsWith("(move")) {
                    kickOffMove = command;
                }
            }
            if (body) {
                times.add(took);
                if (dueCycle != cycles) {
                    dueCycle = cycles;
                    due++;
                }
                takeWaiting();
                if (missedCycle != cycles && late(cycleStart)) {
                    missedCycle = cycles;
                    missed++;
                }
            }
            for (String command : pending) {
                send(command);
            }
        }
        if (think) {
            thinks++;
            send("(done)");
        }
    }

    private void referee(String mode) {
        if (mode.startsWith("goal_") || mode.equals("half_time")) {
            movesOwed = 2;
        } else if (mode.equals("time_over")) {
            gameOver = true;
        }
    }

    /** The kick-off move, sent at the start of a cycle when the player must stand at its spot. */
    private void positionIfNeeded() throws IOException {
        if (kickOffMove == null && cycles == 1) {
            double[] spot = FORMATION[(Math.max(1, unum) - 1) % FORMATION.length];
            kickOffMove = "(move " + format(spot[0]) + " " + format(spot[1]) + ")";
            send(kickOffMove);
        } else if (kickOffMove != null && movesOwed > 0 && brain.repeatsKickOffMove()) {
            movesOwed--;
            send(kickOffMove);
        }
    }

    private static String format(double value) {
        return value == Math.rint(value) ? Long.toString((long) value) : Double.toString(value);
    }

    private static boolean isBody(String command) {
        return command.startsWith("(dash") || command.startsWith("(turn ") || command.startsWith("(kick")
                || command.startsWith("(move") || command.startsWith("(catch") || command.startsWith("(tackle");
    }

    /** Moves everything the socket holds into the queue, in order, without blocking. */
    private void takeWaiting() throws IOException {
        for (Datagram waiting = link.poll(); waiting != null; waiting = link.poll()) {
            heard(waiting);
        }
    }

    private void heard(Datagram datagram) {
        queue.add(datagram);
        lastHeard = datagram.receivedNanos();
    }

    /** Whether what waits in the queue shows the server has moved past the cycle being answered. */
    private boolean late(boolean answeringSenseBody) {
        if (synchronous) {
            return false;
        }
        int sameTime = 0;
        for (Datagram waiting : queue) {
            if (waiting.startsWith("(sense_body ")) {
                int time = waiting.time();
                if (answeringSenseBody || time > lastTime || (time == lastTime && ++sameTime == 2)) {
                    return true;
                }
            }
        }
        return false;
    }

    private void send(String command) throws IOException {
        link.send(command);
        commands++;
        if (log != null) {
            log.sent(command);
        }
    }

    private void bye() {
        try {
            send("(bye)");
        } catch (IOException e) {
            // the server is gone already; nothing to say goodbye to
        }
    }

    private void malformed(Datagram datagram, ProtocolException e) {
        String kind = head(datagram.bytes());
        if (malformed.merge(kind, 1L, Long::sum) == 1) {
            String text = datagram.text();
            notices.accept(name() + ": skipped a malformed " + kind + " message (" + e.getMessage() + "): "
                    + (text.length() > 80 ? text.substring(0, 80) + "..." : text) + "; more of this kind are only counted");
        }
    }

    private long malformedCount() {
        return malformed.values().stream().mapToLong(Long::longValue).sum();
    }

    /** The word after the opening parenthesis, or a description when there is none. */
    static String head(byte[] bytes) {
        if (bytes.length == 0) {
            return "empty";
        }
        if (bytes[0] != '(') {
            return "unbracketed";
        }
        int end = 1;
        while (end < bytes.length && bytes[end] != ' ' && bytes[end] != '(' && bytes[end] != ')' && end < 40) {
            end++;
        }
        return end == 1 ? "headless" : new String(bytes, 1, end - 1, StandardCharsets.UTF_8);
    }

    private Message parseQuietly(Datagram datagram) {
        try {
            return parser.parse(datagram.bytes(), 0, datagram.bytes().length);
        } catch (ProtocolException e) {
            return null;
        }
    }

    private void closeLog() {
        if (log == null) {
            return;
        }
        try {
            Path written = log.commit();
            log = null;
            notices.accept(name() + ": traffic logged to " + written);
        } catch (IOException e) {
            notices.accept(name() + ": could not write its traffic log: " + e.getMessage());
        } finally {
            try {
                if (log != null) {
                    log.close();
                }
            } catch (IOException ignored) {
                // already reported
            }
        }
    }

    private PlayerReport fail(Outcome outcome, String reason) {
        notices.accept(name() + ": " + reason);
        return report(outcome, reason);
    }

    private PlayerReport report(Outcome outcome, String reason) {
        Map<String, Long> counters = brain.counters();
        return new PlayerReport(options.team(), unum, side, outcome, reason, cycles, due, missed, times.count(),
                times.meanMillis(), times.percentileMillis(99), times.maxMillis(), thinks, commands, errors,
                malformed, counters);
    }

    private static String seconds(long millis) {
        return millis % 1000 == 0 ? Long.toString(millis / 1000) : String.format(Locale.ROOT, "%.1f", millis / 1000.0);
    }
}
