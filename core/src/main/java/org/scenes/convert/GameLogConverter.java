package org.scenes.convert;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.function.Predicate;
import org.scenes.gamelog.CommandLogReader;
import org.scenes.gamelog.GameFrame;
import org.scenes.gamelog.GameLogException;
import org.scenes.gamelog.GameLogReader;
import org.scenes.gamelog.GameLogWriter;
import org.scenes.gamelog.PlayerState;
import org.scenes.protocol.Message;
import org.scenes.protocol.MessageParser;
import org.scenes.protocol.Parameters;
import org.scenes.scene.Observer;
import org.scenes.scene.Side;
import org.scenes.vision.Fading;
import org.scenes.vision.SeeWriter;
import org.scenes.vision.VisionNumbers;
import org.scenes.vision.VisionParams;

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

    /** Where one player's scenes go. */
    @FunctionalInterface
    public interface Output {
        SceneConverter.SceneSink open(Observer observer) throws IOException;
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

    private final SceneConverter converter;
    private final Fading fading;
    private final Predicate<Observer> selected;

    /**
     * @param converter makes the scenes (grid, pairing)
     * @param fading how a seen player's team and number fade with distance
     * @param selected which players get scenes (all are seen by the others)
     */
    public GameLogConverter(SceneConverter converter, Fading fading, Predicate<Observer> selected) {
        this.converter = Objects.requireNonNull(converter, "converter");
        this.fading = Objects.requireNonNull(fading, "fading");
        this.selected = Objects.requireNonNull(selected, "selected");
    }

    /**
     * Converts one game. A truncated game log (its last line cut) gives a warning and the scenes
     * up to there; a game log out of order, or a command log of another game (team names or
     * executed commands disagree), is a {@link GameLogException} or {@link LogException} naming
     * the file and line.
     */
    public Result convert(Path gameLog, Path commandLog, Output output) throws IOException {
        try (CommandLogReader commands = CommandLogReader.open(commandLog)) {
            Run run = new Run(gameLog, commands, output);
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
        }
    }

    /** A rebuilt player: its log being converted and how it sees. */
    private static final class Player {
        final Observer observer;
        final SceneConverter.Feed feed;
        SeeWriter writer;
        boolean synchSee;
        int version;
        int type = -1;
        /** The executed command counts at the last frame, and whether a body command was sent since. */
        int executed = -1;
        boolean sentBody;

        Player(Observer observer, SceneConverter.Feed feed) {
            this.observer = observer;
            this.feed = feed;
        }
    }

    private final class Run {
        final Path gameLog;
        final CommandLogReader commands;
        final Output output;
        final List<String> warnings = new ArrayList<>();
        final MessageParser parser = new MessageParser();
        final Map<String, String> serverParam = new HashMap<>();
        final Map<Integer, Map<String, String>> playerTypes = new HashMap<>();
        final Map<String, Player> players = new LinkedHashMap<>();
        /** Versions from the players' init commands (the command log holds them before the game). */
        final Map<String, Integer> versions = new HashMap<>();
        final Map<String, Boolean> synchSee = new HashMap<>();
        /** Command log entries read but not yet delivered, in order. */
        final ArrayDeque<CommandLogReader.Entry> ahead = new ArrayDeque<>();
        final StringBuilder text = new StringBuilder(4096);
        byte[] bytes = new byte[4096];
        boolean commandsEnded;
        boolean teamsKnown;
        int lastCommandTime = -1;
        long frames;
        int lastTime = -1;
        int lastStoppage;
        String lastMode;
        long step;
        String leftTeam = "";
        String rightTeam = "";
        double visibleAngle = 90;
        double sendStep = 150;
        double simulatorStep = 100;
        long agreed;
        long disagreed;
        long lastLine;

        Run(Path gameLog, CommandLogReader commands, Output output) {
            this.gameLog = gameLog;
            this.commands = commands;
            this.output = output;
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
            } else if (params.head().equals("player_type") && params.named().containsKey("id")) {
                playerTypes.put((int) params.number("id"), params.named());
            }
        }

        private static double number(Parameters params, String name, double fallback) {
            double value = params.number(name);
            return Double.isNaN(value) ? fallback : value;
        }

        boolean truncated(GameLogException e) {
            String message = e.getMessage();
            return frames > 0 && (message.contains("ends inside a list") || message.contains("ends before its closing"));
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
            if (!mode.equals(lastMode)) {
                // a step the game log skipped (before kick-off, half time): the referee's word tells which
                stoppage = Math.max(stoppage, announced(time, mode, stoppage));
            }
            if (frames == 0) {
                step = time + stoppage;
            } else if (time == lastTime) {
                step += stoppage - lastStoppage;
            } else {
                step += (time - lastTime) + stoppage;
            }
            deliverBefore(time, stoppage);
            boolean seesDue = !mode.equals("time_over");
            for (PlayerState state : frame.players()) {
                if (state.state() == 0) {
                    continue;
                }
                Player player = player(frame, state);
                if (player == null) {
                    continue;
                }
                checkAgreement(player, state);
                line(player, "(sense_body " + time + ")");
                if (seesDue) {
                    int sees = seesDue(player, state);
                    for (int i = 0; i < sees; i++) {
                        see(player, state, frame);
                    }
                }
            }
            deliverAt(time, stoppage);
            lastTime = time;
            lastStoppage = stoppage;
            lastMode = mode;
            frames++;
        }

        /** The stoppage of the referee's announcement of {@code mode} at {@code time}, or -1. */
        int announced(int time, String mode, int from) throws IOException {
            fillThrough(time);
            for (CommandLogReader.Entry entry : ahead) {
                if (entry.time() == time && entry.stoppage() >= from && entry.referee()
                        && GameLogWriter.playMode(entry.text()).equals(mode)) {
                    return entry.stoppage();
                }
            }
            return -1;
        }

        /** Reads the command log until an entry after {@code time} (kept ahead) or its end. */
        void fillThrough(int time) throws IOException {
            while (!commandsEnded && (ahead.isEmpty() || ahead.peekLast().time() <= time)) {
                if (!readOne()) {
                    return;
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

        /** Delivers what players sent in steps before ({@code time}, {@code stoppage}). */
        void deliverBefore(int time, int stoppage) throws IOException {
            while (true) {
                if (ahead.isEmpty() && !readOne()) {
                    return;
                }
                CommandLogReader.Entry entry = ahead.peekFirst();
                if (!entry.before(time, stoppage)) {
                    return;
                }
                deliver(ahead.pollFirst());
            }
        }

        /** Delivers what players sent in the step ({@code time}, {@code stoppage}), after its see. */
        void deliverAt(int time, int stoppage) throws IOException {
            while (true) {
                if (ahead.isEmpty() && !readOne()) {
                    return;
                }
                CommandLogReader.Entry entry = ahead.peekFirst();
                if (entry.time() != time || entry.stoppage() != stoppage) {
                    return;
                }
                deliver(ahead.pollFirst());
            }
        }

        void deliver(CommandLogReader.Entry entry) throws IOException {
            lastLine = entry.line();
            if (entry.referee()) {
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
                versions.put(key, version(message));
                return;
            }
            Player player = players.get(key);
            if (message.startsWith("(synch_see)")) {
                synchSee.put(key, true);
                if (player != null && !player.synchSee) {
                    player.synchSee = true;
                    line(player, "(ok synch_see)");
                }
                return;
            }
            if (player == null) {
                return; // before the game log's first show, or a player not converted
            }
            if (isBody(message)) {
                player.sentBody = true;
            }
            line(player, message);
        }

        /** The player of a show's slot, its log started on first sight; null when not selected. */
        Player player(GameFrame frame, PlayerState state) throws IOException {
            String team = state.side() == Side.LEFT ? frame.leftTeam() : frame.rightTeam();
            String key = team + "_" + state.unum();
            Player player = players.get(key);
            if (player != null) {
                return player;
            }
            if (players.containsKey(key)) {
                return null;
            }
            Observer observer = new Observer(team, state.side(), state.unum());
            if (!selected.test(observer)) {
                players.put(key, null);
                return null;
            }
            player = new Player(observer, converter.feed(Path.of(gameLog + "#" + key), output.open(observer)));
            players.put(key, player);
            player.version = versions.getOrDefault(key, 0);
            line(player, "(init " + team + " (version " + Math.max(player.version, 3) + "))");
            line(player, "(init " + state.side().letter() + ' ' + state.unum() + ' ' + frame.playMode() + ")");
            // clients of version 18 and later see synchronously from their init on
            if (player.version >= 18 || synchSee.getOrDefault(key, false)) {
                player.synchSee = true;
                line(player, "(ok synch_see)");
            }
            return player;
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
                boolean rose = executed > player.executed;
                if (rose == player.sentBody) {
                    agreed++;
                } else {
                    disagreed++;
                }
                judgeAgreement(false);
            }
            player.executed = executed;
            player.sentBody = false;
        }

        /** Refuses a command log whose commands disagree with the game log's executed counts. */
        void judgeAgreement(boolean atEnd) {
            long compared = agreed + disagreed;
            boolean due = atEnd ? compared >= AGREEMENT_SAMPLE : compared == AGREEMENT_SAMPLE * 10L;
            if (due && disagreed > DISAGREEMENT_REFUSED * compared) {
                throw new LogException(commands.file(), lastLine, String.format(java.util.Locale.ROOT,
                        "the commands of %.0f %% of %d player steps disagree with what %s says was executed:"
                                + " the command log of another game?", 100.0 * disagreed / compared, compared,
                        gameLog.getFileName()), null);
            }
        }

        /** How many sees the player gets after this show: the server's timing as the simulator keeps it. */
        int seesDue(Player player, PlayerState state) {
            // The show was written at the end of step `step`; its sees go out in the next step.
            long next = step + 1;
            double factor = state.viewWidth() / visibleAngle;
            if (player.synchSee) {
                // synchronous: cones of 2/3, 4/3 and 2 visible_angle for a see every 1, 2, 3 steps
                int every = (int) Math.max(1, Math.round(factor * 1.5));
                return next % every == 0 ? 1 : 0;
            }
            double period = sendStep * factor * (state.viewQuality() == 'h' ? 1 : 0.5);
            double begin = next * simulatorStep;
            double end = begin + simulatorStep;
            double first = Math.ceil(begin / period - 1e-9) * period;
            return first < end - 1e-9 ? (int) Math.floor((end - 1e-9 - first) / period) + 1 : 0;
        }

        void see(Player player, PlayerState self, GameFrame frame) throws IOException {
            if (player.writer == null || player.type != self.type()) {
                player.type = self.type();
                player.writer = new SeeWriter(VisionParams.of(serverParam,
                        player.version >= 18 ? playerTypes.get(self.type()) : null), fading);
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

        void line(Player player, CharSequence message) throws IOException {
            int length = message.length();
            if (bytes.length < length * 3) {
                bytes = new byte[Math.max(length * 3, bytes.length * 2)];
            }
            int n = 0;
            boolean ascii = true;
            for (int i = 0; i < length; i++) {
                char c = message.charAt(i);
                if (c >= 0x80) {
                    ascii = false;
                    break;
                }
                bytes[n++] = (byte) c;
            }
            if (!ascii) {
                byte[] encoded = message.toString().getBytes(StandardCharsets.UTF_8);
                player.feed.line(encoded, 0, encoded.length);
                return;
            }
            player.feed.line(bytes, 0, n);
        }

        Result finish() throws IOException {
            // what was sent after the last show; entries more than a step past it belong to no show
            int beyond = 0;
            CommandLogReader.Entry firstBeyond = null;
            CommandLogReader.Entry lastEntry = null;
            while (!ahead.isEmpty() || readOne()) {
                CommandLogReader.Entry entry = ahead.pollFirst();
                lastEntry = entry;
                if (frames > 0 && entry.time() > lastTime + 1) {
                    beyond++;
                    firstBeyond = firstBeyond == null ? entry : firstBeyond;
                } else {
                    deliver(entry);
                }
            }
            if (frames == 0) {
                throw new LogException(gameLog, 0, "no show in the game log: nothing to rebuild", null);
            }
            if (firstBeyond != null) {
                warnings.add(commands.file() + ":" + firstBeyond.line() + ": the command log goes on to cycle "
                        + lastEntry.time() + " (" + beyond + " lines) after the game log's last show at cycle "
                        + lastTime + ": a cut game log, or the command log of another game; those lines were left out");
            } else if (lastCommandTime + 1 < lastTime) {
                warnings.add(commands.file() + ": the command log ends at cycle " + lastCommandTime
                        + ", the game log goes on to cycle "
                        + lastTime + ": later scenes have no actions and are dropped");
            }
            judgeAgreement(true);
            List<PlayerResult> results = new ArrayList<>();
            for (Player player : players.values()) {
                if (player != null) {
                    results.add(new PlayerResult(player.observer, player.feed.finish(0)));
                }
            }
            return new Result(frames, results, warnings);
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

    /** Whether a line a player sent holds a body command, which the server counts once executed. */
    static boolean isBody(String message) {
        return message.contains("(dash ") || message.contains("(turn ") || message.contains("(kick ")
                || message.contains("(move ") || message.contains("(catch ") || message.contains("(tackle ");
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
