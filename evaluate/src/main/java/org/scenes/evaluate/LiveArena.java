package org.scenes.evaluate;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Random;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;
import java.util.function.IntConsumer;
import java.util.stream.Stream;
import org.scenes.agent.net.ClientOptions;
import org.scenes.agent.net.PlayerReport;
import org.scenes.agent.net.TeamRunner;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.GameLogReader;
import org.scenes.internal.protocol.Hear;
import org.scenes.internal.protocol.InitReply;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.SenseBody;
import org.scenes.simulator.Brain;
import org.scenes.simulator.BrainFactory;
import org.scenes.simulator.GameResult;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.Simulator;

/**
 * Games on a live soccer server (rcssserver, or {@code scenes server}) through the project's UDP
 * runtime ({@link TeamRunner}): the left team connects player by player, then the right team,
 * and the server plays the game. A server plays one game per connection of the teams, so each
 * game waits (up to {@code serverWait}) until the server accepts the left team: a series of
 * {@code scenes server --games N}, or rcssserver restarted in a loop.
 *
 * <p>What the game gives without the server's help comes from the players' own traffic: the
 * score from the referee's {@code goal_*} messages, kicks from the {@code sense_body} kick
 * counters (rcssserver counts kicks that reached the ball), the game's length from
 * {@code time_over}. Positions (frames) come only from the server's game log: with a log
 * directory, the {@code .rcg} the server completed there during the game is read; without one,
 * the game has no frames.
 *
 * <p>An {@link ExternalTeam} plays on the right, its command started once ours is connected; a game
 * of two external teams (none of ours) is played by {@link ExternalGame}, the left team's command
 * first and watched through a relay.
 *
 * <p>Each brain is made when its player's init is answered, seeded from the game seed, side and
 * uniform number as the embedded simulator seeds it, so on {@code scenes server} with the same
 * seed a game starts exactly as in process.
 */
public final class LiveArena implements Arena {
    private static final long POLL_MILLIS = 200;
    /** How long the server may take to complete its game log after time over. */
    private static final Duration LOG_WAIT = Duration.ofSeconds(20);

    private final ClientOptions client;
    private final Path serverLogs;
    private final Duration serverWait;
    private final Consumer<String> notices;

    /**
     * @param client where the server is and how players connect (the team name is each team's own)
     * @param serverLogs where the server writes its game logs ({@code .rcg}); null for none
     * @param serverWait how long to keep trying until the server accepts a game's first player
     * @param notices one-line messages for the user
     */
    public LiveArena(ClientOptions client, Path serverLogs, Duration serverWait, Consumer<String> notices) {
        this.client = Objects.requireNonNull(client, "client");
        this.serverLogs = serverLogs;
        this.serverWait = Objects.requireNonNull(serverWait, "serverWait");
        this.notices = Objects.requireNonNull(notices, "notices");
    }

    @Override
    public GameResult play(GameSetup setup, IntConsumer progress, Consumer<GameFrame> frames) throws IOException {
        boolean externalLeft = setup.left().brains() instanceof ExternalTeam;
        if (externalLeft && !(setup.right().brains() instanceof ExternalTeam)) {
            throw new IllegalArgumentException("an external team plays on the right: ours connects first");
        }
        Scoreboard board = new Scoreboard();
        List<PlayerReport> reports = new ArrayList<>();
        FileTime begun;
        try {
            if (externalLeft) {
                begun = new ExternalGame(client, serverWait).play(setup, board, progress);
                return finish(setup, board, reports, begun, progress, frames);
            }
            Connected left = connect(setup.left(), Side.LEFT, setup.seed(), board, reports, System.nanoTime()
                    + serverWait.toNanos());
            // the server took this game, so the previous game's log is complete: a log newer than this is ours
            begun = FileTime.fromMillis(System.currentTimeMillis());
            if (setup.right().brains() instanceof ExternalTeam external) {
                playAgainst(external, setup.right(), left, board, progress);
            } else {
                // the right team only once the left is complete: the first team to connect is the left one
                Connected right = connect(setup.right(), Side.RIGHT, setup.seed(), board, reports, System.nanoTime()
                        + client.connectTimeout().toNanos() * 2);
                while (left.thread().isAlive() || right.thread().isAlive()) {
                    progress.accept(board.time.get());
                    left.thread().join(POLL_MILLIS);
                    right.thread().join(1);
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while playing on " + client.server());
        }
        return finish(setup, board, reports, begun, progress, frames);
    }

    /** The game's result once it is over: the players' failures, the clock, the score and the game log. */
    private GameResult finish(GameSetup setup, Scoreboard board, List<PlayerReport> reports, FileTime begun,
                              IntConsumer progress, Consumer<GameFrame> frames) throws IOException {
        for (PlayerReport report : reports) {
            if (!report.outcome().ok()) {
                throw new IOException(report.team() + " player " + report.unum() + " on " + client.server() + ": "
                        + report.reason());
            }
        }
        if (!board.timeOver) {
            throw new IOException("the game on " + client.server() + " ended before time over");
        }
        int cycles = board.time.get();
        if (cycles != setup.cycles()) {
            notices.accept("the server at " + client.server() + " played " + cycles + " cycles, not the "
                    + setup.cycles() + " asked for: figures are per 1000 cycles of the game played");
        }
        progress.accept(cycles);
        List<Path> logs = new ArrayList<>();
        if (serverLogs != null) {
            Path log = awaitGameLog(begun);
            readFrames(log, setup, frames);
            logs.add(log);
        }
        return new GameResult(board.score[0].get(), board.score[1].get(), board.kicks(Side.LEFT),
                board.kicks(Side.RIGHT), cycles, cycles, logs);
    }

    /**
     * Starts the team's runner and waits until all its players are connected, trying again
     * (until {@code deadline}) while the server does not accept the first one.
     */
    private Connected connect(GameSetup.Team team, Side side, long seed, Scoreboard board, List<PlayerReport> reports,
                              long deadline) throws InterruptedException, IOException {
        String lastReason = "";
        while (true) {
            // each try waits for its answer at most until the deadline (and at least a second)
            Duration answer = Duration.ofNanos(Math.max(1_000_000_000L,
                    Math.min(client.connectTimeout().toNanos(), deadline - System.nanoTime())));
            ClientOptions options = new ClientOptions(client.server(), team.name(), client.version(), false, 0,
                    answer, client.silenceTimeout(), client.logDirectory());
            AtomicInteger connected = new AtomicInteger();
            AtomicReference<String> wrongSide = new AtomicReference<>();
            TeamRunner runner = new TeamRunner(options, team.players(),
                    seeded(team.brains(), seed, side, board, connected, wrongSide, notices), seed, line -> {
                        // a try while the server takes no game yet is not news; its reason is kept in the report
                        if (connected.get() > 0) {
                            notices.accept(line);
                        }
                    });
            Thread thread = new Thread(() -> {
                try {
                    List<PlayerReport> played = runner.play();
                    synchronized (reports) {
                        reports.addAll(played);
                    }
                } catch (InterruptedException e) {
                    runner.stop();
                    Thread.currentThread().interrupt();
                }
            }, team.name() + "-team");
            thread.setDaemon(true);
            thread.start();
            while (thread.isAlive() && connected.get() < team.players() && wrongSide.get() == null) {
                thread.join(20);
            }
            if (wrongSide.get() != null) {
                runner.stopAndAwait();
                throw new IOException(team.name() + " was given the " + wrongSide.get() + " side by " + client.server()
                        + ": is another team connected?");
            }
            if (connected.get() == team.players()) {
                return new Connected(thread, runner);
            }
            thread.join();
            List<PlayerReport> failed;
            synchronized (reports) {
                failed = List.copyOf(reports);
                reports.clear();
            }
            if (connected.get() > 0) {
                throw new IOException(team.name() + ": only " + connected.get() + " of " + team.players()
                        + " players were accepted by " + client.server() + reasons(failed));
            }
            lastReason = reasons(failed);
            if (System.nanoTime() > deadline) {
                throw new IOException("no game on " + client.server() + " accepted " + team.name() + " within "
                        + serverWait.toSeconds() + " s" + lastReason);
            }
            Thread.sleep(500);
        }
    }

    /** Our team on the server: the thread running it and the runner to stop it. */
    private record Connected(Thread thread, TeamRunner runner) {
    }

    /**
     * Starts the external team's command once ours is connected (so it takes the right side), waits
     * until the server starts the game (the clock our players hear runs: no game starts without the
     * other team) and plays it to the end; the command's whole process group is ended afterwards,
     * and ours stopped if the command fails.
     */
    private void playAgainst(ExternalTeam external, GameSetup.Team team, Connected ours, Scoreboard board,
                             IntConsumer progress) throws IOException, InterruptedException {
        Path output = Files.createTempFile("scenes-team-" + team.name() + "-", ".log");
        boolean failed = true;
        try (ExternalTeam.Running running = external.start(client.server().host(), client.server().port(),
                team.name(), team.players(), output)) {
            long deadline = System.nanoTime() + serverWait.toNanos();
            while (board.time.get() < 1 && !board.timeOver && ours.thread().isAlive()) {
                if (!running.alive()) {
                    throw new IOException(team.name() + ": the command '" + running.command() + "' ended (exit "
                            + running.exitCode() + ") before the game began" + quoted(running.lastWords()));
                }
                if (System.nanoTime() > deadline) {
                    throw new IOException(team.name() + ": no player of the command '" + running.command()
                            + "' joined the game on " + client.server() + " within " + serverWait.toSeconds() + " s"
                            + quoted(running.lastWords()));
                }
                ours.thread().join(POLL_MILLIS);
            }
            while (ours.thread().isAlive()) {
                progress.accept(board.time.get());
                ours.thread().join(POLL_MILLIS);
                if (!running.alive() && !board.timeOver && ours.thread().isAlive()) {
                    throw new IOException(team.name() + ": the command '" + running.command() + "' ended (exit "
                            + running.exitCode() + ") at cycle " + board.time.get() + ", before time over"
                            + quoted(running.lastWords()));
                }
            }
            failed = false;
        } finally {
            if (failed) {
                ours.runner().stopAndAwait();
            }
            Files.deleteIfExists(output);
        }
    }

    static String quoted(String lastWords) {
        return lastWords.isEmpty() ? "" : " (it said: " + lastWords + ")";
    }

    private static String reasons(List<PlayerReport> reports) {
        return reports.stream().map(PlayerReport::reason).filter(r -> !r.isEmpty()).findFirst().map(r -> " (" + r + ")")
                .orElse("");
    }

    /**
     * Brains made as each player's init is answered, seeded as the embedded simulator seeds
     * them, behind the scoreboard.
     */
    static BrainFactory seeded(BrainFactory brains, long seed, Side side, Scoreboard board,
                                       AtomicInteger connected, AtomicReference<String> wrongSide,
                                       Consumer<String> notices) {
        // the runner makes the players' brains in order and starts each player once the one before was answered,
        // so the server numbers them 1, 2, ... in the order made (answers are handled on the players' own threads)
        AtomicInteger made = new AtomicInteger();
        return (teamName, ignored) -> new Brain() {
            private final MessageParser parser = new MessageParser();
            private final int expected = made.incrementAndGet();
            private Brain inner;
            private int unum;

            @Override
            public void receive(String message, Consumer<String> send) {
                if (inner == null) {
                    InitReply init = PlayerNumber.given(parser, message);
                    if (init == null) {
                        return;
                    }
                    if (init.side() != side) {
                        wrongSide.set(init.side() == Side.LEFT ? "left" : "right");
                        return;
                    }
                    unum = init.uniformNumber();
                    inner = brains.create(teamName, new Random(Simulator.brainSeed(seed, side, unum)));
                    connected.incrementAndGet();
                    if (unum != expected) {
                        notices.accept(teamName + " player " + expected + " was given uniform number " + unum
                                + ": the server holds a player of an earlier try (answered too late?); the game"
                                + " is played, but not with the numbers and seeds of the game in process");
                    }
                }
                board.heard(side, unum, message, parser);
                inner.receive(message, send);
            }

            /** The brain's own answer once it is made (the runtime asks after a goal or half time). */
            @Override
            public boolean repeatsKickOffMove() {
                return inner == null || inner.repeatsKickOffMove();
            }
        };
    }

    /**
     * The newest game log the server completed since the game began, waiting for it a while: a
     * {@code .rcg} or {@code .rcg.gz} not named {@code incomplete} (rcssserver writes that name
     * during the game, and renames it at the end unless told to keep a fixed name).
     */
    private Path awaitGameLog(FileTime begun) throws IOException {
        long deadline = System.nanoTime() + LOG_WAIT.toNanos();
        while (true) {
            Path newest = null;
            FileTime newestTime = begun;
            try (Stream<Path> files = Files.list(serverLogs)) {
                for (Path file : files.toList()) {
                    String name = file.getFileName().toString();
                    if (!(name.endsWith(".rcg") || name.endsWith(".rcg.gz")) || name.startsWith("incomplete")) {
                        continue;
                    }
                    FileTime modified = Files.getLastModifiedTime(file);
                    if (modified.compareTo(newestTime) > 0) {
                        newest = file;
                        newestTime = modified;
                    }
                }
            }
            if (newest != null) {
                return newest;
            }
            if (System.nanoTime() > deadline) {
                throw new IOException("the server wrote no game log in " + serverLogs + " within "
                        + LOG_WAIT.toSeconds() + " s of time over (is it the server's game log directory?)");
            }
            try {
                Thread.sleep(POLL_MILLIS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IOException("interrupted while waiting for the game log in " + serverLogs);
            }
        }
    }

    private static void readFrames(Path log, GameSetup setup, Consumer<GameFrame> frames) throws IOException {
        List<GameFrame> read = GameLogReader.readAll(log);
        GameFrame last = read.isEmpty() ? null : read.get(read.size() - 1);
        if (last == null || !last.leftTeam().equals(setup.left().name()) || !last.rightTeam().equals(setup.right().name())) {
            throw new IOException(log + " is not this game's log: it is "
                    + (last == null ? "empty" : last.leftTeam() + " against " + last.rightTeam()) + ", not "
                    + setup.left().name() + " against " + setup.right().name());
        }
        read.forEach(frames);
    }

    /** What the players hear of the game: the clock, the score, time over, and their kick counters. */
    static final class Scoreboard {
        final AtomicInteger time = new AtomicInteger();
        final AtomicInteger[] score = {new AtomicInteger(), new AtomicInteger()};
        final ConcurrentHashMap<String, Integer> kickCounters = new ConcurrentHashMap<>();
        volatile boolean timeOver;

        void heard(Side side, int unum, String message, MessageParser parser) {
            if (message.startsWith("(sense_body ")) {
                if (parser.parse(message) instanceof SenseBody body) {
                    time.accumulateAndGet(body.time(), Math::max);
                    if (body.counts().kick() >= 0) {
                        kickCounters.merge(side + "_" + unum, body.counts().kick(), Math::max);
                    }
                }
            } else if (message.startsWith("(hear ") && message.contains(" referee ")
                    && parser.parse(message) instanceof Hear hear && hear.speaker() == Hear.Speaker.REFEREE) {
                String mode = hear.text().trim();
                if (mode.startsWith("goal_l_") || mode.startsWith("goal_r_")) {
                    try {
                        score[mode.charAt(5) == 'l' ? 0 : 1].accumulateAndGet(Integer.parseInt(mode.substring(7)),
                                Math::max);
                    } catch (NumberFormatException e) {
                        // a goal word without its count: the score stays as the last count said
                    }
                } else if (mode.equals("time_over")) {
                    time.accumulateAndGet(hear.time(), Math::max);
                    timeOver = true;
                }
            }
        }

        int kicks(Side side) {
            String prefix = side + "_";
            return kickCounters.entrySet().stream().filter(e -> e.getKey().startsWith(prefix))
                    .mapToInt(Map.Entry::getValue).sum();
        }
    }
}
