package org.scenes.internal.convert;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.function.Predicate;
import org.scenes.api.Grid;
import org.scenes.api.Observer;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.CommandLogReader;
import org.scenes.internal.gamelog.CommandSource;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.GameLogException;
import org.scenes.internal.gamelog.GameLogReader;
import org.scenes.internal.gamelog.GameLogWriter;
import org.scenes.internal.gamelog.PlayerState;
import org.scenes.internal.protocol.Message;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.Parameters;
import org.scenes.internal.vision.Fading;
import org.scenes.internal.vision.SeeWriter;
import org.scenes.internal.vision.VisionNumbers;
import org.scenes.internal.vision.VisionParams;

/**
 * Scenes for every player of a game from the server's own logs: the game log ({@code .rcg},
 * where everything was each step) and the command log ({@code .rcl}, what each player sent).
 * Each player's messages are rebuilt step by step, in the order the player got and sent them
 * ({@code sense_body}, the {@code see} the server would have sent, by {@link SeeWriter}, then the
 * commands of that step), and converted by {@link SceneConverter} under the rules of player logs
 * (docs/conversion.md, "Scenes from game logs"). Streams both logs: memory grows with the
 * number of players, not with the game's length.
 */
public final class GameLogConverter {
    /** Share of player steps whose executed commands may disagree with the command log before it is refused. */
    private static final double DISAGREEMENT_REFUSED = 0.2;
    /** Player steps compared before judging. */
    private static final int AGREEMENT_SAMPLE = 200;
    /** Cycles of a player's commands read ahead to infer the phase of its see clock. */
    private static final int PHASE_WINDOW = 300;
    /**
     * Cycles of what a player did that decide its see clock when the timing of its commands did not
     * (measured on three real-server games of the project's Krislet: 17 of 18 right from 300 cycles,
     * all 18 from 600); the steps are held meanwhile.
     */
    private static final int CONTENT_WINDOW = 1000;
    /** Commands more that another phase must explain, as a share of those read, to replace the first step's. */
    private static final double PHASE_MARGIN = 0.1;
    /** Steps of the candidate phases, in ms. */
    private static final double PHASE_GRAIN = 2.5;

    /** Where an asynchronous player's see clock starts. */
    public enum SeePhase {
        /** Multiples of the see period from the first step, as the project's simulator keeps it. */
        FIRST_STEP,
        /**
         * rcssserver's: the player's own see counter, started at the first tick after its connection;
         * the command log gives the connection's step, not the tick: of the candidates the one that
         * explains clearly most of the player's commands (a see-driven player answers in the cycle
         * of a see), else the first; when the commands' timing tells the candidates not apart, the
         * one whose sees best explain what the player did ({@link PhaseEvidence}). Without the
         * step, the same among offsets from the first step's.
         */
        INFER
    }

    /** Where one player's scenes go. */
    @FunctionalInterface
    public interface Output {
        SceneConverter.SceneSink open(Observer observer) throws IOException;

        /** The same for a player the game log marks as its team's goalie or not. */
        default SceneConverter.SceneSink open(Observer observer, boolean goalie) throws IOException {
            return open(observer);
        }
    }

    /** One player's conversion. */
    public record PlayerResult(Observer observer, ConversionReport report) {
        /** {@code TEAM_UNUM}, the player's name in the command log. */
        public String key() {
            return observer.team() + "_" + observer.uniformNumber();
        }
    }

    /**
     * @param frames shows read from the game log
     * @param warnings what was wrong but left the scenes sound, each naming the file and line
     */
    public record Result(long frames, List<PlayerResult> players, List<String> warnings) {
    }

    private final Grid grid;
    private final Pairing pairing;
    private final Fading fading;
    private final Predicate<Observer> selected;
    private final int threads;
    private boolean commandsBeforeSee;
    private SeePhase seePhase = SeePhase.INFER;
    private boolean keepUnanswered;
    private boolean world;

    /**
     * @param grid and {@code pairing} make the scenes, as for player logs
     * @param fading how a seen player's team and number fade with distance
     * @param selected which players get scenes (all are seen by the others)
     * @param threads threads rebuilding and converting the players (each player on one)
     */
    public GameLogConverter(Grid grid, Pairing pairing, Fading fading, Predicate<Observer> selected, int threads) {
        this.grid = Objects.requireNonNull(grid, "grid");
        this.pairing = Objects.requireNonNull(pairing, "pairing");
        this.fading = Objects.requireNonNull(fading, "fading");
        this.selected = Objects.requireNonNull(selected, "selected");
        if (threads < 1) {
            throw new IllegalArgumentException("threads must be 1 or more, not " + threads);
        }
        this.threads = threads;
    }

    /**
     * Within a step, the player's commands come before its see, right after {@code sense_body}
     * ({@code true}), or (the default) before it only when the player already holds a see taken
     * after its last command took effect, otherwise after it (players answer what they see; see
     * {@code Worker.commandsFirst}). The command log does not say.
     */
    public GameLogConverter commandsBeforeSee(boolean before) {
        this.commandsBeforeSee = before;
        return this;
    }

    /** Unanswered sees become scenes without action, as {@link SceneConverter.Builder#keepUnanswered}. */
    public GameLogConverter keepUnanswered(boolean keep) {
        this.keepUnanswered = keep;
        return this;
    }

    /**
     * Whether each scene carries the player's world model, built from the rebuilt percepts (then
     * each {@code sense_body} carries the player's state and the referee's calls are heard); default false.
     */
    public GameLogConverter world(boolean world) {
        this.world = world;
        return this;
    }

    /** Where asynchronous players' see clocks start (default {@link SeePhase#INFER}). */
    public GameLogConverter seePhase(SeePhase phase) {
        this.seePhase = Objects.requireNonNull(phase, "phase");
        return this;
    }

    /**
     * Converts one game. A truncated game log (its last line cut) gives a warning and the scenes
     * up to there; a game log out of order, or a command log of another game (team names or
     * executed commands disagree), is a {@link GameLogException} or {@link LogException} naming
     * the file and line.
     */
    public Result convert(Path gameLog, Path commandLog, Output output) throws IOException {
        try (CommandLogReader commands = CommandLogReader.open(commandLog)) {
            return convert(gameLog, commands, output);
        }
    }

    /**
     * Converts one game whose commands come from {@code commands} (a command log, or those inferred
     * from the game log); as {@link #convert(Path, Path, Output)}. The caller closes the source.
     */
    public Result convert(Path gameLog, CommandSource commands, Output output) throws IOException {
        Run run = new Run(gameLog, commands, output);
        try {
            try {
                GameLogReader.forEach(gameLog, run::frame, run::parameters);
            } catch (UncheckedIOException e) {
                throw e.getCause();
            } catch (GameLogException e) {
                if (!run.truncated(e)) {
                    throw e;
                }
                run.warnings.add(e.getMessage() + "; the game log is cut there: scenes up to cycle " + run.lastTime
                        + " kept");
            }
            return run.finish();
        } finally {
            run.stopWorkers();
        }
    }

    /**
     * Where an asynchronous player's see clock may start: the likeliest offset, the candidates, and
     * whether the timing of its commands told them apart.
     */
    private record Phase(double offset, List<Double> candidates, boolean told) {
        /** The first step's clock, nothing to decide. */
        static final Phase FIRST_STEP = new Phase(0, List.of(0.0), true);
    }

    /** A player whose see clock waits for what it did in its first cycles, from {@code from} on. */
    private record Undecided(Player player, int from, List<Double> candidates) {
    }

    /** What a player sent, for its worker. */
    private record Sent(Player player, String message) {
    }

    /** One show and what was sent around it, handed to every worker. */
    private record Step(GameFrame frame, long index, List<Sent> before, List<Sent> at, boolean seesDue,
                        List<Player> players, Set<Player> synchSees, boolean commandsCover) {
    }

    private static final Step END = new Step(null, 0, List.of(), List.of(), false, List.of(), Set.of(), false);

    /** A rebuilt player: its log being converted and how it sees; touched by its worker only once started. */
    private static final class Player {
        final Observer observer;
        final String key;
        final SceneConverter.SceneSink sink;
        final Worker worker;
        final int version;
        final Fading fading;
        /** Whether the game log marks the player as its team's goalie (at its first show). */
        boolean goalie;
        /** Set by the reading thread when the player's first show is handed out. */
        boolean started;
        /** The play mode the player was last told (world models only). */
        String heardMode;
        SceneConverter.Feed feed;
        SeeWriter writer;
        boolean synchSee;
        /**
         * Where the player's asynchronous see clock starts, in ms from the first step's start; set by
         * the reading thread before the player's first step is handed out.
         */
        double seeOffset;
        int type = -1;
        /** The executed command counts at the last show, and whether a body command was sent since. */
        int executed = -1;
        boolean sentBody;
        /** The steps of the player's last see and last command, to order the two within a step. */
        long seeStep = -1;
        long commandStep = -1;
        long agreed;
        long disagreed;

        Player(Observer observer, String key, SceneConverter.SceneSink sink, Worker worker, int version,
               boolean synchSee, double seeOffset, Fading fading) {
            this.seeOffset = seeOffset;
            this.observer = observer;
            this.key = key;
            this.sink = sink;
            this.worker = worker;
            this.version = version;
            this.synchSee = synchSee;
            this.fading = fading;
        }
    }

    /** Rebuilds and converts its players, step by step, on a thread of its own (or the caller's). */
    private final class Worker implements Runnable {
        final Run run;
        final SceneConverter converter = SceneConverter.with(grid).pairing(pairing).world(world)
                .keepUnanswered(keepUnanswered).build();
        final BlockingQueue<Step> queue;
        final StringBuilder text = new StringBuilder(4096);
        /** This worker's own: a parser serves one thread. */
        final MessageParser parser = new MessageParser();
        byte[] bytes = new byte[4096];
        volatile Throwable failure;
        Thread thread;

        Worker(Run run, boolean threaded) {
            this.run = run;
            this.queue = threaded ? new ArrayBlockingQueue<>(64) : null;
        }

        @Override
        public void run() {
            try {
                while (true) {
                    Step step = queue.take();
                    if (step == END) {
                        return;
                    }
                    if (failure == null) {
                        process(step);
                    }
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            } catch (IOException | RuntimeException | Error e) {
                failure = e;
                queue.clear();
            }
        }

        void submit(Step step) throws IOException {
            if (queue == null) {
                process(step);
                return;
            }
            rethrow();
            try {
                queue.put(step);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new java.io.InterruptedIOException("interrupted");
            }
        }

        void rethrow() throws IOException {
            Throwable e = failure;
            if (e instanceof IOException io) {
                throw io;
            } else if (e instanceof RuntimeException runtime) {
                throw runtime;
            } else if (e instanceof Error error) {
                throw error;
            }
        }

        void process(Step step) throws IOException {
            GameFrame frame = step.frame();
            if (frame == null) {
                // what was sent after the last show
                for (Sent sent : step.before()) {
                    if (sent.player().worker == this && sent.player().feed != null) {
                        deliver(sent.player(), sent.message());
                    }
                }
                return;
            }
            for (Player player : step.players()) {
                if (player.worker == this && player.feed == null) {
                    start(player, frame);
                }
            }
            for (Sent sent : step.before()) {
                if (sent.player().worker == this) {
                    deliver(sent.player(), sent.message());
                    sent.player().commandStep = step.index();
                }
            }
            int time = frame.time();
            for (PlayerState state : frame.players()) {
                Player player = run.slot(frame, state);
                if (player == null || player.worker != this) {
                    continue;
                }
                if (step.commandsCover()) {
                    checkAgreement(player, state);
                }
                if (converter.world()) {
                    // the world model reads the player's own state and the referee's calls
                    senseBody(player, state, time);
                    referee(player, frame);
                } else {
                    line(player, "(sense_body " + time + ")");
                }
                // this show's sees and commands belong to the next step
                long next = step.index() + 1;
                List<String> sent = sentBy(player, step);
                int first = commandsFirst(player, sent.size());
                deliver(player, sent.subList(0, first), next);
                if (step.seesDue()) {
                    int sees = seesDue(player, state, step);
                    for (int i = 0; i < sees; i++) {
                        see(player, state, frame);
                        player.seeStep = next;
                    }
                }
                deliver(player, sent.subList(first, sent.size()), next);
            }
        }

        /**
         * How many of the player's {@code sent} commands of the coming step went out before its
         * see. The command log does not say. A player that already holds a see taken after its last
         * command took effect (a see of a later step than that command's) has what it needs and
         * answers it at the step's start, as Krislet does; one that does not waits for the step's
         * see; of several commands in a step, all but the last answered earlier sees. Synchronous
         * sees come with {@code sense_body}, so commands follow them.
         */
        int commandsFirst(Player player, int sent) {
            if (commandsBeforeSee) {
                return sent;
            }
            if (sent == 0 || player.synchSee) {
                return 0;
            }
            return player.seeStep > player.commandStep ? Math.max(1, sent - 1) : sent - 1;
        }

        List<String> sentBy(Player player, Step step) {
            List<String> sent = List.of();
            for (Sent s : step.at()) {
                if (s.player() == player) {
                    if (sent.isEmpty()) {
                        sent = new ArrayList<>(2);
                    }
                    sent.add(s.message());
                }
            }
            return sent;
        }

        void deliver(Player player, List<String> messages, long index) throws IOException {
            for (String message : messages) {
                deliver(player, message);
                player.commandStep = index;
            }
        }

        void start(Player player, GameFrame frame) throws IOException {
            player.feed = converter.feed(Path.of(run.gameLog + "#" + player.key), player.sink);
            Observer o = player.observer;
            line(player, "(init " + o.team() + " (version " + Math.max(player.version, 3) + ")"
                    + (player.goalie ? " (goalie)" : "") + ")");
            line(player, "(init " + o.side().letter() + ' ' + o.uniformNumber() + ' ' + frame.playMode() + ")");
            player.heardMode = frame.playMode();
            if (player.synchSee) {
                line(player, "(ok synch_see)");
            }
        }

        void deliver(Player player, String message) throws IOException {
            if (message.startsWith("(synch_see)")) {
                if (!player.synchSee) {
                    player.synchSee = true;
                    line(player, "(ok synch_see)");
                }
                return;
            }
            if (BodyCommands.first(parser, message) != null) {
                player.sentBody = true;
            }
            line(player, message);
        }

        /**
         * The game log's counts of executed commands against the command log: a body command the
         * player sent in a step shows as a count rising by the next show. Another game's command log
         * disagrees in most steps.
         */
        void checkAgreement(Player player, PlayerState state) {
            PlayerState.Counts c = state.counts();
            int executed = c.kick() + c.dash() + c.turn() + c.catches() + c.move() + c.tackle();
            if (player.executed >= 0) {
                if ((executed > player.executed) == player.sentBody) {
                    player.agreed++;
                } else {
                    player.disagreed++;
                }
            }
            player.executed = executed;
            player.sentBody = false;
        }

        /**
         * How many sees the player gets after this show: synchronous ones as the reading thread's
         * {@link SynchSeeCounter} decided, asynchronous ones by the player's see clock.
         */
        int seesDue(Player player, PlayerState state, Step step) {
            if (player.synchSee) {
                return step.synchSees().contains(player) ? 1 : 0;
            }
            // The show was written at the end of its step; its sees go out in the next step.
            return asynchSees(step.index() + 1, run.period(state), player.seeOffset, run.simulatorStep);
        }

        void see(Player player, PlayerState self, GameFrame frame) throws IOException {
            if (player.writer == null || player.type != self.type()) {
                player.type = self.type();
                player.writer = new SeeWriter(VisionParams.of(run.serverParam,
                        player.version >= 18 ? run.playerTypes.get(self.type()) : null), player.fading);
            }
            SeeWriter writer = player.writer;
            text.setLength(0);
            double head = VisionNumbers.normalize(self.body() + self.neck());
            writer.begin(text, frame.time(), self.x(), self.y(), self.vx(), self.vy(), head, self.viewWidth(),
                    self.viewQuality() == 'h');
            writer.landmarks();
            GameFrame.BallState ball = frame.ball();
            writer.ball(ball.x(), ball.y(), ball.vx(), ball.vy());
            for (PlayerState other : frame.players()) {
                if (other == self || other.state() == 0) {
                    continue;
                }
                String team = other.side() == Side.LEFT ? frame.leftTeam() : frame.rightTeam();
                writer.player(other.x(), other.y(), other.vx(), other.vy(), team, other.unum(),
                        (other.state() & PlayerState.GOALIE) != 0, other.body(),
                        VisionNumbers.normalize(other.body() + other.neck()));
            }
            writer.lines();
            writer.end();
            line(player, text);
        }

        /**
         * The player's {@code sense_body} as the server writes it (version 7's fields, which the
         * world model reads): stamina, speed relative to the head, neck angle, command counts.
         */
        void senseBody(Player player, PlayerState self, int time) throws IOException {
            double speed = Math.hypot(self.vx(), self.vy());
            double head = self.body() + self.neck();
            double direction = speed < 1e-9 ? 0
                    : Math.rint(VisionNumbers.normalize(Math.toDegrees(Math.atan2(self.vy(), self.vx())) - head));
            PlayerState.Counts c = self.counts();
            text.setLength(0);
            text.append("(sense_body ").append(time).append(" (view_mode ")
                    .append(self.viewQuality() == 'h' ? "high " : "low ")
                    .append(self.viewWidth() <= 60 ? "narrow" : self.viewWidth() >= 180 ? "wide" : "normal")
                    .append(") (stamina ");
            VisionNumbers.append(text, Math.rint(self.stamina()), 0).append(' ');
            VisionNumbers.append(text, self.effort(), 6).append(' ');
            VisionNumbers.append(text, self.capacity(), 0).append(") (speed ");
            VisionNumbers.append(text, VisionNumbers.quantize(speed, 0.01), 2).append(' ');
            VisionNumbers.append(text, direction, 0).append(") (head_angle ");
            VisionNumbers.append(text, Math.rint(self.neck()), 0).append(") (kick ").append(c.kick())
                    .append(") (dash ").append(c.dash()).append(") (turn ").append(c.turn())
                    .append(") (say ").append(c.say()).append(") (turn_neck ").append(c.turnNeck())
                    .append(") (catch ").append(c.catches()).append(") (move ").append(c.move())
                    .append(") (change_view ").append(c.changeView()).append("))");
            line(player, text);
        }

        /** The referee's call when the play mode changed since the player last heard ({@code goal_l_2} for goals). */
        void referee(Player player, GameFrame frame) throws IOException {
            String mode = frame.playMode();
            if (mode.equals(player.heardMode)) {
                return;
            }
            player.heardMode = mode;
            String word = mode.equals("goal_l") ? "goal_l_" + frame.scoreLeft()
                    : mode.equals("goal_r") ? "goal_r_" + frame.scoreRight() : mode;
            line(player, "(hear " + frame.time() + " referee " + word + ")");
        }

        void line(Player player, CharSequence message) throws IOException {
            int length = message.length();
            if (bytes.length < length) {
                bytes = new byte[Math.max(length, bytes.length * 2)];
            }
            for (int i = 0; i < length; i++) {
                char c = message.charAt(i);
                if (c >= 0x80) {
                    byte[] encoded = message.toString().getBytes(StandardCharsets.UTF_8);
                    player.feed.line(encoded, 0, encoded.length);
                    return;
                }
                bytes[i] = (byte) c;
            }
            player.feed.line(bytes, 0, length);
        }
    }

    private final class Run {
        final Path gameLog;
        final CommandSource commands;
        final Output output;
        final List<String> warnings = new ArrayList<>();
        final MessageParser parser = new MessageParser();
        final Map<String, String> serverParam = new HashMap<>();
        final Map<Integer, Map<String, String>> playerTypes = new HashMap<>();
        /** Every player of the game by TEAM_UNUM; null for those not selected. */
        final Map<String, Player> players = new LinkedHashMap<>();
        /** The players by show slot (side, number), for the workers: set before a step is handed out. */
        final Player[][] slots = new Player[2][64];
        /** Versions from the players' init commands (the command log holds them before the game). */
        final Map<String, Integer> versions = new HashMap<>();
        final Map<String, Boolean> synchSee = new HashMap<>();
        /** Command log entries read but not yet delivered, in order. */
        final ArrayDeque<CommandLogReader.Entry> ahead = new ArrayDeque<>();
        final List<Worker> workers = new ArrayList<>();
        boolean commandsEnded;
        boolean teamsKnown;
        int lastCommandTime = -1;
        long frames;
        int lastTime = -1;
        int lastStoppage;
        String lastMode;
        long step;
        /** The server's step of {@link #step} 0: the steps before the game log's first show. */
        long serverShift;
        /** The cycle of the last goal the referee announced. */
        int goalCycle = -1;
        /** The server's step of each player's init, by TEAM_UNUM. */
        final Map<String, Long> initSteps = new HashMap<>();
        /** Players whose see clocks their commands' timing did not tell, and the steps held meanwhile. */
        final List<Undecided> undecided = new ArrayList<>();
        final ArrayDeque<Step> held = new ArrayDeque<>();
        /** Each player's synchronous see counter, by TEAM_UNUM, from its init on. */
        final Map<String, SynchSeeCounter> counters = new HashMap<>();
        /** The server's step of converter step 0, and the current show's step and time. */
        long serverOffset;
        long lastStep;
        int showTime = -1;
        int showStoppage;
        String leftTeam = "";
        String rightTeam = "";
        double visibleAngle = 90;
        double sendStep = 150;
        double simulatorStep = 100;
        double visibleDistance = 3;
        long lastLine;
        int nextWorker;

        Run(Path gameLog, CommandSource commands, Output output) {
            this.gameLog = gameLog;
            this.commands = commands;
            this.output = output;
            for (int i = 0; i < threads; i++) {
                Worker worker = new Worker(this, threads > 1);
                if (threads > 1) {
                    worker.thread = new Thread(worker, "rebuild-" + i);
                    worker.thread.setDaemon(true);
                    worker.thread.start();
                }
                workers.add(worker);
            }
        }

        void parameters(String line) {
            Message message = parser.parse(line);
            if (!(message instanceof Parameters params)) {
                return;
            }
            if (params.head().equals("server_param")) {
                serverParam.putAll(params.named());
                visibleAngle = number(params, "visible_angle", visibleAngle);
                sendStep = number(params, "send_step", sendStep);
                simulatorStep = number(params, "simulator_step", simulatorStep);
                visibleDistance = number(params, "visible_distance", visibleDistance);
            } else if (params.head().equals("player_type") && params.named().containsKey("id")) {
                playerTypes.put((int) params.number("id"), params.named());
            }
        }

        private static double number(Parameters params, String name, double fallback) {
            double value = params.number(name);
            return Double.isNaN(value) ? fallback : value;
        }

        boolean truncated(GameLogException e) {
            return frames > 0 && e.cutOff();
        }

        Player slot(GameFrame frame, PlayerState state) {
            if (state.state() == 0 || state.unum() < 0 || state.unum() >= 64) {
                return null;
            }
            return slots[state.side() == Side.LEFT ? 0 : 1][state.unum()];
        }

        void frame(GameFrame frame) {
            try {
                step(frame);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }

        void step(GameFrame frame) throws IOException {
            int time = frame.time();
            if (frames > 0 && time < lastTime) {
                // named with the game log's line by the reader
                throw new IllegalArgumentException("cycle " + time + " comes after cycle " + lastTime
                        + ": the game log is out of order");
            }
            leftTeam = frame.leftTeam();
            rightTeam = frame.rightTeam();
            teamsKnown = true;
            String mode = frame.playMode();
            int stoppage = frames > 0 && time == lastTime ? lastStoppage + 1 : 0;
            if (!mode.equals(lastMode) || (time != lastTime && pausedAt(time))) {
                // steps the game log skipped (before kick-off, half time): the referee's word tells
                // how many, also when the mode is the same on both sides (a kick-off not taken by half time)
                stoppage = Math.max(stoppage, announced(time, mode, stoppage));
            }
            if (frames == 0) {
                // steps from 0; a standing clock's first step has stoppage 1
                step = time + Math.max(0, stoppage - 1);
                // the server's steps before: those of cycle 0 (before kick-off) when the log starts later
                serverShift = time > 0 ? lastStoppageAt(0, 0) : 0;
                serverOffset = (time == 0 ? stoppage : time + serverShift + stoppage) - step;
            } else {
                step = stepAfterLast(time, stoppage);
            }
            showTime = time;
            showStoppage = stoppage;
            // what was sent before this show: the players' inits (versions) come before their first show
            List<Sent> before = new ArrayList<>();
            collect(before, time, stoppage, true);
            List<Player> starting = new ArrayList<>(0);
            for (PlayerState state : frame.players()) {
                if (state.state() != 0) {
                    Player player = player(frame, state);
                    if (player != null && !player.started) {
                        player.started = true;
                        starting.add(player);
                    }
                }
            }
            Set<Player> synchSees = synchSees(frame);
            List<Sent> at = new ArrayList<>();
            collect(at, time, stoppage, false);
            // past the end of a cut command log nothing was sent as far as it tells: not evidence of another game
            boolean covered = !commandsEnded || time <= lastCommandTime;
            hand(new Step(frame, step, before, at, !mode.equals("time_over"), starting, synchSees, covered));
            lastTime = time;
            lastStoppage = stoppage;
            lastStep = step;
            lastMode = mode;
            frames++;
        }

        /**
         * The converter's step of ({@code time}, {@code stoppage}), after the last show's. The
         * stoppage steps of the cycles since that show which the game log skipped (rcssserver's
         * JSON log has no show of the half-time break) the command log tells.
         */
        long stepAfterLast(int time, int stoppage) throws IOException {
            if (time == lastTime) {
                return lastStep + stoppage - lastStoppage;
            }
            return lastStep + (time - lastTime) + stoppage + skippedStoppage(lastTime, lastStoppage, time);
        }

        /** The server's step a command log entry was received in. */
        long serverStep(CommandLogReader.Entry entry) throws IOException {
            if (entry.time() == showTime && entry.stoppage() == showStoppage) {
                return step + serverOffset;
            }
            if (frames == 0) {
                // before the first show: the clock stands before kick-off, its steps are the stoppage
                return entry.time() == 0 ? entry.stoppage() : entry.time() + serverShift + entry.stoppage();
            }
            return stepAfterLast(entry.time(), entry.stoppage()) + serverOffset;
        }

        /**
         * The players of this show who get a synchronous see with it: their counters raised
         * through the show's step, the last step's interval the show's view width.
         */
        Set<Player> synchSees(GameFrame frame) {
            Set<Player> due = null;
            long at = step + serverOffset;
            for (PlayerState state : frame.players()) {
                Player player = slot(frame, state);
                SynchSeeCounter counter = player == null ? null : counters.get(player.key);
                if (counter == null || !counter.synch()) {
                    continue; // (the worker's Player.synchSee is its own)
                }
                counter.interval(at - 1, (int) Math.max(1, Math.round(state.viewWidth() / visibleAngle * 1.5)));
                if (counter.advance(at)) {
                    due = due == null ? new HashSet<>() : due;
                    due.add(player);
                }
            }
            return due == null ? Set.of() : due;
        }

        /** The player's counter from its init (the server's step 0 when the command log has none). */
        SynchSeeCounter counter(String key, boolean synch) {
            return counters.computeIfAbsent(key, k -> new SynchSeeCounter(0, 2, synch));
        }

        /** What a player's message does to its see counter: {@code synch_see}, {@code change_view}. */
        void countSees(String key, String message, CommandLogReader.Entry entry) throws IOException {
            if (message.startsWith("(synch_see)")) {
                counter(key, false).startSynch(serverStep(entry));
                return;
            }
            for (int at = message.indexOf("(change_view "); at >= 0; at = message.indexOf("(change_view ", at + 1)) {
                int end = message.indexOf(')', at);
                String[] words = message.substring(at + 13, end < 0 ? message.length() : end).strip().split("\\s+");
                SynchSeeCounter counter = counter(key, false);
                int interval = SynchSeeCounter.interval(words[0]);
                // synchronous sees are of high quality only: the server ignores a change to low
                boolean ignored = words.length > 2 || counter.synch() && words.length == 2 && !words[1].equals("high");
                if (interval > 0 && !ignored) {
                    counter.interval(serverStep(entry), interval);
                }
            }
        }

        void submit(Step work) throws IOException {
            for (Worker worker : workers) {
                worker.submit(work);
            }
        }

        /** Hands a step to the workers, or holds it while a player's see clock is undecided. */
        void hand(Step work) throws IOException {
            if (undecided.isEmpty() && held.isEmpty()) {
                submit(work);
                return;
            }
            held.add(work);
            decide(work.frame().time());
        }

        /**
         * Sets the see clocks of the undecided players whose first {@link #CONTENT_WINDOW} cycles were
         * read by {@code time}; once none is left, hands out the steps held.
         */
        void decide(int time) throws IOException {
            undecided.removeIf(u -> {
                if (u.from() + CONTENT_WINDOW > time) {
                    return false;
                }
                u.player().seeOffset = byContent(u);
                return true;
            });
            if (undecided.isEmpty()) {
                while (!held.isEmpty()) {
                    submit(held.pollFirst());
                }
            }
        }

        /**
         * Of the undecided player's candidate clocks, the one whose sees best explain what it did in
         * the steps held (see {@link PhaseEvidence}); the first when none explains more.
         */
        double byContent(Undecided u) {
            Player player = u.player();
            PhaseEvidence evidence = new PhaseEvidence(u.candidates(), simulatorStep, visibleDistance);
            for (Step step : held) {
                for (Sent sent : step.before()) {
                    if (sent.player() == player) {
                        evidence.command(BodyCommands.first(parser, sent.message()));
                    }
                }
                for (PlayerState state : step.frame().players()) {
                    if (slot(step.frame(), state) == player) {
                        GameFrame.BallState ball = step.frame().ball();
                        // the show's sees go out in the next step, before or with its commands
                        evidence.show(step.index() + 1, period(state), state, ball.x(), ball.y());
                    }
                }
                for (Sent sent : step.at()) {
                    if (sent.player() == player) {
                        evidence.command(BodyCommands.first(parser, sent.message()));
                    }
                }
            }
            return u.candidates().get(evidence.best());
        }

        /** The period of a player's asynchronous sees in its view mode, in ms. */
        double period(PlayerState state) {
            return sendStep * state.viewWidth() / visibleAngle * (state.viewQuality() == 'h' ? 1 : 0.5);
        }

        /**
         * The phase of an asynchronous player's see clock, in ms from the first step's start: of the
         * {@link #candidates}, the one whose sees fall in the steps of most of the player's commands
         * of the next {@link #PHASE_WINDOW} cycles (up to its first {@code change_view}); the first
         * unless another explains clearly more. When every candidate explains about as many (a
         * player on a clock of its own), the timing has not told, and what the player did decides
         * ({@link #byContent}). A command logged in a cycle belongs to the step after that cycle's
         * show, the step its see is sent in.
         */
        Phase seeOffset(String key, int time, PlayerState state) throws IOException {
            if (seePhase == SeePhase.FIRST_STEP) {
                return Phase.FIRST_STEP;
            }
            readThrough(time + PHASE_WINDOW);
            long shift = step - time + 1;
            // the stoppage steps of the cycles passed (a goal, half time) shift the later ones
            int cycle = time;
            int cycleStoppage = 0;
            List<Long> steps = new ArrayList<>();
            for (CommandLogReader.Entry entry : ahead) {
                if (entry.time() >= time + PHASE_WINDOW) {
                    break;
                }
                if (entry.time() < time) {
                    continue;
                }
                if (entry.time() != cycle) {
                    shift += cycleStoppage;
                    cycle = entry.time();
                    cycleStoppage = 0;
                }
                if (entry.referee()) {
                    continue; // the kick-off after a goal is logged past the cycle's last step
                }
                cycleStoppage = Math.max(cycleStoppage, entry.stoppage());
                if (!key.equals(entry.team() + "_" + entry.unum()) || entry.text().startsWith("(init ")) {
                    continue;
                }
                if (entry.text().contains("(change_view ")) {
                    break;
                }
                steps.add(entry.time() + entry.stoppage() + shift);
            }
            double period = period(state);
            List<Double> candidates = candidates(initSteps.get(key), period);
            double first = candidates.get(0);
            double bestOffset = first;
            int firstScore = explained(steps, period, first);
            int best = firstScore;
            int worst = firstScore;
            for (double offset : candidates.subList(1, candidates.size())) {
                int score = explained(steps, period, offset);
                worst = Math.min(worst, score);
                if (score > best) {
                    best = score;
                    bestOffset = offset;
                }
            }
            double margin = PHASE_MARGIN * steps.size();
            // every candidate explains the commands alike: a player on a clock of its own
            boolean told = best - worst > margin;
            return new Phase(best - firstScore > margin ? bestOffset : first, candidates, told);
        }

        /**
         * The offsets the player's see clock may have, the likeliest first. With its init's step known
         * (rcssserver's command log counts the steps before kick-off as stoppage), its counter's
         * first tick is the first {@code send_step / 4} tick after the init arrived, any time in
         * that step: one of the 3 or 4 ticks from the step's start to a tick past its end; its first
         * see comes {@code interval} ticks on; the first tick is taken unless commands tell otherwise.
         * Without it (or at step 0, as the project's simulator logs every init), any offset in
         * {@link #PHASE_GRAIN} ms steps, 0 first.
         */
        List<Double> candidates(Long initStep, double period) {
            List<Double> offsets = new ArrayList<>();
            if (initStep == null || initStep == 0) {
                for (double offset = 0; offset < period - 1e-9; offset += PHASE_GRAIN) {
                    offsets.add(offset);
                }
                return offsets;
            }
            double tick = sendStep / 4;
            long interval = Math.max(1, Math.round(period / tick));
            double from = initStep * simulatorStep;
            double until = from + simulatorStep + tick;
            for (long t = (long) Math.floor(from / tick + 1e-9) + 1; t * tick < until - 1e-9; t++) {
                // the server's step g sends the sees of the cycle it makes: this converter's step g - shift + 1
                double see = (t + interval - 1) * tick - (serverShift - 1) * simulatorStep;
                offsets.add(((see % period) + period) % period);
            }
            return offsets;
        }

        private int explained(List<Long> steps, double period, double offset) {
            int count = 0;
            for (long s : steps) {
                if (asynchSees(s, period, offset, simulatorStep) > 0) {
                    count++;
                }
            }
            return count;
        }

        /**
         * The last step of cycle {@code time} the command log shows (its last stoppage still ahead,
         * at least {@code from}). rcssserver logs the kick-off after a goal one stoppage past the
         * cycle's last step (its players get 51 {@code sense_body} of the goal's cycle, the kick-off
         * is at stoppage 51); before kick-off and at half time, in the last step.
         */
        int lastStoppageAt(int time, int from) throws IOException {
            readThrough(time);
            int last = from;
            boolean goal = goalCycle == time;
            for (CommandLogReader.Entry entry : ahead) {
                if (entry.time() > time) {
                    break;
                }
                if (entry.time() != time) {
                    continue;
                }
                goal |= entry.referee() && entry.text().startsWith("goal_");
                if (!(goal && entry.referee() && entry.text().startsWith("kick_off_"))) {
                    last = Math.max(last, entry.stoppage());
                }
            }
            return last;
        }

        /**
         * The stoppage steps the command log holds for the cycles from {@code from} (after its
         * stoppage {@code counted}) to before {@code to}, which no show between them counted.
         */
        long skippedStoppage(int from, int counted, int to) throws IOException {
            long skipped = 0;
            for (int time = from; time < to && time <= from + 1000; time++) {
                int base = time == from ? counted : 0;
                skipped += lastStoppageAt(time, base) - base;
            }
            return skipped;
        }

        /** The stoppage of the referee's announcement of {@code mode} at {@code time}, or -1. */
        int announced(int time, String mode, int from) throws IOException {
            readThrough(time);
            for (CommandLogReader.Entry entry : ahead) {
                if (entry.time() == time && entry.stoppage() >= from && entry.referee()
                        && GameLogWriter.playMode(entry.text()).equals(mode)) {
                    return entry.stoppage();
                }
            }
            return -1;
        }

        /** Whether the referee announced {@code before_kick_off} at {@code time}: the game log skips what follows. */
        boolean pausedAt(int time) throws IOException {
            readThrough(time);
            for (CommandLogReader.Entry entry : ahead) {
                if (entry.time() > time) {
                    break;
                }
                if (entry.time() == time && entry.referee()
                        && GameLogWriter.playMode(entry.text()).equals("before_kick_off")) {
                    return true;
                }
            }
            return false;
        }

        /** Reads the command log ahead past {@code time}. */
        void readThrough(int time) throws IOException {
            while (!commandsEnded && (ahead.isEmpty() || ahead.peekLast().time() <= time)) {
                if (!readOne()) {
                    break;
                }
            }
        }

        boolean readOne() throws IOException {
            CommandLogReader.Entry entry = commands.next();
            if (entry == null) {
                commandsEnded = true;
                return false;
            }
            ahead.addLast(entry);
            lastCommandTime = entry.time();
            return true;
        }

        /**
         * What players sent in steps before ({@code time}, {@code stoppage}) (or, when not
         * {@code before}, in that step, after its see), for the players' workers.
         */
        void collect(List<Sent> into, int time, int stoppage, boolean before) throws IOException {
            while (true) {
                if (ahead.isEmpty() && !readOne()) {
                    return;
                }
                CommandLogReader.Entry entry = ahead.peekFirst();
                boolean wanted = before ? entry.before(time, stoppage)
                        : entry.time() == time && entry.stoppage() == stoppage;
                if (!wanted) {
                    return;
                }
                route(ahead.pollFirst(), into);
            }
        }

        void route(CommandLogReader.Entry entry, List<Sent> into) throws IOException {
            lastLine = entry.line();
            if (entry.referee()) {
                if (entry.text().startsWith("goal_")) {
                    goalCycle = entry.time();
                }
                return;
            }
            String team = entry.team();
            if (teamsKnown && !team.equals(leftTeam) && !team.equals(rightTeam)) {
                throw new LogException(commands.file(), entry.line(), team + "_" + entry.unum()
                        + " plays in neither team of " + gameLog.getFileName() + " (" + leftTeam + ", " + rightTeam
                        + "): the command log of another game?", null);
            }
            String key = team + "_" + entry.unum();
            String message = entry.text();
            if (message.startsWith("(init ")) {
                int version = version(message);
                versions.put(key, version);
                long at = serverStep(entry);
                initSteps.put(key, at);
                // clients of version 18 and later see synchronously from their init on
                counters.put(key, new SynchSeeCounter(at, 2, version >= 18));
                return;
            }
            countSees(key, message, entry);
            Player player = players.get(key);
            if (player == null) {
                if (message.startsWith("(synch_see)")) {
                    synchSee.put(key, true);
                }
                return; // before the player's first show, or a player not converted
            }
            into.add(new Sent(player, message));
        }

        /** The player of a show's slot, made on first sight; null when not selected. */
        Player player(GameFrame frame, PlayerState state) throws IOException {
            String team = state.side() == Side.LEFT ? frame.leftTeam() : frame.rightTeam();
            String key = team + "_" + state.unum();
            if (players.containsKey(key)) {
                return players.get(key);
            }
            Observer observer = new Observer(team, state.side(), state.unum());
            Player player = null;
            if (selected.test(observer)) {
                int version = versions.getOrDefault(key, initAhead(key, frame.time()));
                // clients of version 18 and later see synchronously from their init on
                double factor = state.viewWidth() / visibleAngle;
                boolean synch = version >= 18 || synchSee.getOrDefault(key, false)
                        // cones only synchronous vision has (60 and 120 degrees): a log without the init
                        || Math.abs(factor - 2.0 / 3) < 1e-6 || Math.abs(factor - 4.0 / 3) < 1e-6;
                Phase phase = synch ? Phase.FIRST_STEP : seeOffset(key, frame.time(), state);
                boolean goalie = (state.state() & PlayerState.GOALIE) != 0;
                player = new Player(observer, key, output.open(observer, goalie), workers.get(nextWorker++ % threads),
                        version, synch, phase.offset(), fading.forObserver(key));
                player.goalie = goalie;
                if (!phase.told()) {
                    undecided.add(new Undecided(player, frame.time(), phase.candidates()));
                }
                if (synch) {
                    // synchronous without an init or synch_see in the command log: from the server's step 0
                    counter(key, true).startSynch(0);
                }
                if (state.unum() >= 0 && state.unum() < 64) {
                    slots[state.side() == Side.LEFT ? 0 : 1][state.unum()] = player;
                }
            }
            players.put(key, player);
            return player;
        }

        /** The version of the player's init sent by the end of {@code time} (ahead of its show), or 0. */
        int initAhead(String key, int time) throws IOException {
            readThrough(time);
            for (CommandLogReader.Entry entry : ahead) {
                if (entry.time() > time) {
                    break;
                }
                if (!entry.referee() && entry.text().startsWith("(init ")
                        && key.equals(entry.team() + "_" + entry.unum())) {
                    return version(entry.text());
                }
            }
            return 0;
        }

        Result finish() throws IOException {
            // what was sent after the last show; entries more than a step past it belong to no show
            int beyond = 0;
            CommandLogReader.Entry firstBeyond = null;
            List<Sent> after = new ArrayList<>();
            while (!ahead.isEmpty() || readOne()) {
                CommandLogReader.Entry entry = ahead.pollFirst();
                if (frames > 0 && entry.time() > lastTime + 1) {
                    beyond++;
                    firstBeyond = firstBeyond == null ? entry : firstBeyond;
                } else {
                    route(entry, after);
                }
            }
            if (frames == 0) {
                throw new LogException(gameLog, 0, "no show in the game log: nothing to rebuild", null);
            }
            decide(Integer.MAX_VALUE);
            submit(new Step(null, 0, after, List.of(), false, List.of(), Set.of(), false));
            stopWorkers();
            if (firstBeyond != null) {
                warnings.add(commands.file() + ":" + firstBeyond.line() + ": the command log goes on to cycle "
                        + lastCommandTime + " (" + beyond + " lines) after the game log's last show at cycle "
                        + lastTime + ": a cut game log, or the command log of another game; those lines were left out");
            } else if (lastCommandTime + 1 < lastTime) {
                warnings.add(commands.file() + ": the command log ends at cycle " + lastCommandTime
                        + ", the game log goes on to cycle " + lastTime + ": later scenes have no actions and are dropped");
            }
            long agreed = 0;
            long disagreed = 0;
            List<PlayerResult> results = new ArrayList<>();
            for (Player player : players.values()) {
                if (player != null && player.feed != null) {
                    agreed += player.agreed;
                    disagreed += player.disagreed;
                    results.add(new PlayerResult(player.observer, player.feed.finish(0)));
                }
            }
            long compared = agreed + disagreed;
            if (compared >= AGREEMENT_SAMPLE && disagreed > DISAGREEMENT_REFUSED * compared) {
                throw new LogException(commands.file(), 0, String.format(Locale.ROOT,
                        "the commands of %.0f %% of %d player steps disagree with what %s says was executed:"
                                + " the command log of another game?", 100.0 * disagreed / compared, compared,
                        gameLog.getFileName()), null);
            }
            return new Result(frames, results, warnings);
        }

        /** Ends the workers' threads (once), rethrowing the first failure. */
        void stopWorkers() throws IOException {
            for (Worker worker : workers) {
                if (worker.thread != null && worker.thread.isAlive()) {
                    try {
                        worker.queue.put(END);
                        worker.thread.join();
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                        throw new java.io.InterruptedIOException("interrupted");
                    }
                }
            }
            for (Worker worker : workers) {
                worker.rethrow();
            }
        }

        int version(String init) {
            int at = init.indexOf("(version ");
            if (at < 0) {
                return 3;
            }
            int end = init.indexOf(')', at);
            try {
                return (int) Double.parseDouble(init.substring(at + 9, end).strip());
            } catch (RuntimeException e) {
                return 3;
            }
        }
    }

    /**
     * How many asynchronous sees fall in step {@code step}: those at {@code offset} plus multiples
     * of {@code period} (ms) from the first step's start.
     */
    static int asynchSees(long step, double period, double offset, double simulatorStep) {
        double begin = step * simulatorStep - offset;
        double end = begin + simulatorStep;
        double first = Math.ceil(begin / period - 1e-9) * period;
        return first < end - 1e-9 ? (int) Math.floor((end - 1e-9 - first) / period) + 1 : 0;
    }

    /** Every player of the game: the default selection. */
    public static Predicate<Observer> everyone() {
        return observer -> true;
    }

    /** The players of {@code team} (any when null) with number {@code unum} (any when 0). */
    public static Predicate<Observer> only(String team, int unum) {
        return observer -> (team == null || team.equals(observer.team()))
                && (unum == 0 || unum == observer.uniformNumber());
    }

}
