package org.scenes.internal.convert;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Objects;
import java.util.function.Consumer;
import java.util.function.LongConsumer;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.Observer;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.api.Side;
import org.scenes.api.World;
import org.scenes.internal.protocol.InitReply;
import org.scenes.internal.protocol.InitRequest;
import org.scenes.internal.protocol.Message;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.PlayerCommand;
import org.scenes.internal.protocol.ProtocolException;
import org.scenes.internal.protocol.See;
import org.scenes.internal.protocol.SenseBody;
import org.scenes.internal.protocol.ServerNotice;
import org.scenes.internal.protocol.Unknown;
import org.scenes.internal.protocol.VisualObject;
import org.scenes.internal.scene.Relations;
import org.scenes.internal.world.WorldModel;

/**
 * Turns player logs into scenes (the thesis' LogToScenes, rules in docs/conversion.md): a scene is
 * a {@code see} with the actions the player sent after it and before the next different
 * {@code see}; identical repeated {@code see}s (play paused) collapse into one; scenes without
 * action (unless {@link Builder#keepUnanswered kept}) and actions without {@code see} are dropped and counted. For a player that acts every
 * cycle on synchronous vision ({@link Pairing}), a scene is a cycle (from one {@code sense_body} to
 * the next) with the latest {@code see} and its age. A log line may hold several messages. The
 * live agent uses {@link #seenObjects} for the same see-to-objects step.
 *
 * <p>Streams: one log line at a time, scenes handed to a {@link SceneSink} as they close.
 * Not thread-safe (it owns a {@link MessageParser}); use one converter per thread.
 */
public final class SceneConverter {
    /** Receives each scene as soon as it is complete. */
    @FunctionalInterface
    public interface SceneSink {
        void accept(Scene scene) throws IOException;

        /** Told, before the player's first scene, that its init asked to play as goalie. */
        default void goalie() {
        }

        /** A sink writing scenes to {@code scenes} and telling {@code goalie} of the goalie's init. */
        static SceneSink of(SceneSink scenes, Runnable goalie) {
            return new SceneSink() {
                @Override
                public void accept(Scene scene) throws IOException {
                    scenes.accept(scene);
                }

                @Override
                public void goalie() {
                    goalie.run();
                }
            };
        }
    }

    /** How often (in lines) progress is reported. */
    private static final int PROGRESS_LINES = 4096;

    private final Grid grid;
    private final Pairing pairing;
    private final boolean strict;
    private final Consumer<MalformedLine> warnings;
    private final boolean world;
    /** Whether sees the player left unanswered become scenes without action (else they are dropped). */
    private final boolean keepUnanswered;
    private final MessageParser parser = new MessageParser();

    private SceneConverter(Builder builder) {
        this.grid = builder.grid;
        this.pairing = builder.pairing;
        this.strict = builder.strict;
        this.warnings = builder.warnings;
        this.world = builder.world;
        this.keepUnanswered = builder.keepUnanswered;
    }

    /**
     * A converter computing cells in {@code grid}, with the defaults: {@link Pairing#AUTO}, not
     * strict, malformed lines counted but told to no one. Change them on the builder, then
     * {@link Builder#build}.
     */
    public static Builder with(Grid grid) {
        return new Builder(grid);
    }

    /** The settings of a {@link SceneConverter}, each named: see {@link #with}. */
    public static final class Builder {
        private final Grid grid;
        private Pairing pairing = Pairing.AUTO;
        private boolean strict;
        private Consumer<MalformedLine> warnings = line -> { };
        private boolean world;
        private boolean keepUnanswered;

        private Builder(Grid grid) {
            this.grid = Objects.requireNonNull(grid, "grid");
        }

        /**
         * How sees and actions become scenes ({@link Pairing#AUTO}, the default: per cycle once the
         * server confirms synchronous vision, per see otherwise).
         */
        public Builder pairing(Pairing pairing) {
            this.pairing = Objects.requireNonNull(pairing, "pairing");
            return this;
        }

        /** Whether the first malformed line stops the conversion ({@link LogException}); default false. */
        public Builder strict(boolean strict) {
            this.strict = strict;
            return this;
        }

        /** Told of each malformed line when not strict ({@code null}: no one). */
        public Builder warnings(Consumer<MalformedLine> warnings) {
            this.warnings = warnings == null ? line -> { } : warnings;
            return this;
        }

        /**
         * Whether each scene carries the player's world model ({@link World}, built by
         * {@link WorldModel} from every message of the log); default false.
         */
        public Builder world(boolean world) {
            this.world = world;
            return this;
        }

        /**
         * Whether a see the player left unanswered (no action before the next different see; per
         * cycle, a cycle without action) becomes a scene without action, a learnable "no action",
         * rather than being dropped and counted ({@link DropReason#NO_ACTION}); default false.
         */
        public Builder keepUnanswered(boolean keep) {
            this.keepUnanswered = keep;
            return this;
        }

        public SceneConverter build() {
            return new SceneConverter(this);
        }
    }

    public Grid grid() {
        return grid;
    }

    /** Whether the scenes carry the player's world model. */
    public boolean world() {
        return world;
    }

    /** Converts one log file (any {@link LogFormat}, plain or gzip). */
    public ConversionReport convert(Path log, SceneSink sink) throws IOException {
        return convert(log, sink, bytes -> { });
    }

    /**
     * Converts one log file, telling {@code progress} every few thousand lines how many more bytes
     * of log text were read.
     */
    public ConversionReport convert(Path log, SceneSink sink, LongConsumer progress) throws IOException {
        try (LogReader reader = LogReader.open(log)) {
            return convert(reader, sink, progress);
        }
    }

    /** Converts what the reader has left. */
    public ConversionReport convert(LogReader reader, SceneSink sink, LongConsumer progress) throws IOException {
        Run run = new Run(reader.file(), sink);
        long reported = 0;
        long lines = 0;
        while (reader.next()) {
            run.message(reader);
            if (++lines % PROGRESS_LINES == 0) {
                progress.accept(reader.bytesRead() - reported);
                reported = reader.bytesRead();
            }
        }
        run.finish();
        progress.accept(reader.bytesRead() - reported);
        run.report.log(reader.line(), reader.bytesRead());
        return run.report;
    }

    /**
     * A conversion fed one log line at a time by the caller, for logs made elsewhere (a player's
     * messages rebuilt from a server game log): the same rules as {@link #convert}.
     */
    public Feed feed(Path name, SceneSink sink) {
        return new Feed(new Run(name, sink));
    }

    /** One player's log, line by line: see {@link #feed}. */
    public static final class Feed {
        private final Run run;
        private long line;

        private Feed(Run run) {
            this.run = run;
        }

        /** The next line of the log: one or several messages. */
        public void line(byte[] bytes, int offset, int length) throws IOException {
            line++;
            try {
                run.message(line, null, bytes, offset, length);
            } catch (UncheckedIOException e) {
                throw e.getCause();
            }
        }

        /**
         * The next line of the log, one {@code see} given as the parser would read its text (a see
         * rebuilt from a game log): converted as that line would be.
         */
        public void line(See see) throws IOException {
            line++;
            run.built(see);
        }

        /** The next line of the log, one {@code sense_body} given as the parser would read its text. */
        public void line(SenseBody senseBody) throws IOException {
            line++;
            run.handle(senseBody);
        }

        /** Ends the log: closes the open scene; the report of the whole log. */
        public ConversionReport finish(long bytes) throws IOException {
            run.finish();
            run.report.log(line, bytes);
            return run.report;
        }
    }

    /**
     * The scene objects of one {@code see} for an observer: names, numbers and marks as parsed,
     * the {@link Relation} to the observer, and each object's cell in {@code grid}.
     */
    public static List<SeenObject> seenObjects(See see, Observer observer, Grid grid) {
        List<VisualObject> objects = see.objects();
        List<SeenObject> seen = new ArrayList<>(objects.size());
        for (VisualObject object : objects) {
            seen.add(object.seen(relation(object, observer), grid));
        }
        return seen;
    }

    /** The relation of a parsed object to its observer ({@link Relations#of}). */
    public static Relation relation(VisualObject object, Observer observer) {
        return Relations.of(object.kind(), object.name(), object.team(), observer);
    }

    /** The state of converting one log. */
    private final class Run implements Consumer<Message> {
        final ConversionReport report = new ConversionReport();
        final Path file;
        final SceneSink sink;
        String team = "";
        Side side;
        int uniformNumber;
        Observer observer = Observer.UNKNOWN;
        /** Whether scenes are made per cycle (player acting every cycle) rather than per see. */
        boolean perCycle = pairing == Pairing.CYCLE;
        byte[] lineBytes;
        int lineOffset;
        int lineLength;

        /** The see the open scene shows (per see), or the latest see (per cycle). */
        See pending;
        Observer pendingObserver;
        byte[] pendingBytes = new byte[4096];
        int pendingLength;
        /** Per cycle: whether a scene is open, and its cycle. */
        boolean cycleOpen;
        int openCycle;
        /** Server steps since the latest see arrived, at the open cycle. */
        int openAge;
        Action primary;
        Action secondary;
        boolean orphanActions;
        /** The player's world model, when scenes carry it; per see, its state at the pending see. */
        final WorldModel worldModel = world ? new WorldModel() : null;
        World pendingWorld;

        Run(Path file, SceneSink sink) {
            this.file = file;
            this.sink = sink;
            if (perCycle) {
                report.perCycle();
            }
        }

        void message(LogReader reader) throws IOException {
            message(reader.line(), reader.problem(), reader.buffer(), reader.offset(), reader.length());
        }

        void message(long line, String problem, byte[] bytes, int offset, int length) throws IOException {
            if (problem != null) {
                malformed(line, problem);
                return;
            }
            if (isRepeat(bytes, offset, length)) {
                // byte-for-byte the see that opened the scene: parsed once already
                repeatedSee();
                return;
            }
            lineBytes = bytes;
            lineOffset = offset;
            lineLength = length;
            String coach = CoachLog.evidence(bytes, offset, length);
            if (coach != null) {
                throw new LogException(file, line, "this is an online coach's log (" + coach
                        + "), not a player's: convert the logs of the players", null);
            }
            try {
                // a datagram (log line) may hold several messages, e.g. librcsc's (turn 0)(turn_neck 0)(done)
                parser.parseAll(bytes, offset, length, this);
            } catch (ProtocolException e) {
                malformed(line, e.getMessage());
            } catch (UncheckedIOException e) {
                throw e.getCause();
            }
        }

        @Override
        public void accept(Message message) {
            try {
                handle(message);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }

        void handle(Message message) throws IOException {
            report.message();
            // The world model takes each message: per see before the see opens its scene (the scene
            // holds the model at its see), per cycle after (a scene closes on the next cycle's first
            // message and holds the model of its whole cycle).
            boolean worldFirst = worldModel != null && !perCycle;
            if (worldFirst) {
                worldModel.accept(message);
            }
            pairing(message);
            if (worldModel != null && !worldFirst) {
                worldModel.accept(message);
            }
        }

        void pairing(Message message) throws IOException {
            if (message instanceof See see) {
                if (perCycle) {
                    cycleSee(see);
                } else {
                    see(see);
                }
            } else if (message instanceof SenseBody body) {
                if (perCycle) {
                    senseBody(body);
                }
            } else if (message instanceof PlayerCommand command) {
                command(command);
            } else if (message instanceof InitRequest init) {
                team = init.team();
                observer = new Observer(team, side, uniformNumber);
                if (init.goalie()) {
                    sink.goalie();
                }
            } else if (message instanceof InitReply reply) {
                if (reply.head().equals("reconnect")) {
                    finish();
                }
                side = reply.side();
                uniformNumber = reply.uniformNumber() > 0 ? reply.uniformNumber() : uniformNumber;
                observer = new Observer(team, side, uniformNumber);
            } else if (message instanceof ServerNotice notice) {
                if (pairing == Pairing.AUTO && !perCycle && notice.head().equals("ok")
                        && notice.text().equals("synch_see")) {
                    // synchronous vision: a see every other cycle in normal view, the player acts every cycle
                    finish();
                    perCycle = true;
                    report.perCycle();
                }
            } else if (message instanceof Unknown unknown) {
                report.unknown(unknown.head());
            }
        }

        /** A see given as read: a repeat is an equal see, as a read one is a line of equal bytes. */
        void built(See see) throws IOException {
            if (pending != null && pendingLength < 0 && see.equals(pending)) {
                repeatedSee();
                return;
            }
            lineBytes = null;
            lineLength = -1;
            handle(see);
        }

        /** Counts a see that repeats the pending one: the open scene goes on. */
        void repeatedSee() {
            report.message();
            report.see();
            report.repeatedSee();
        }

        boolean isRepeat(byte[] bytes, int offset, int length) {
            return pending != null && length == pendingLength
                    && Arrays.equals(pendingBytes, 0, length, bytes, offset, offset + length);
        }

        /** Per see: a different see closes the open scene and opens the next. */
        void see(See see) throws IOException {
            report.see();
            close();
            remember(see);
            orphanActions = false;
        }

        /**
         * Per cycle: the see becomes the latest view. Arriving at the start of the open scene's cycle,
         * before any action, it is that scene's view; otherwise it opens a scene of its own.
         */
        void cycleSee(See see) throws IOException {
            report.see();
            remember(see);
            orphanActions = false;
            if (cycleOpen && openCycle == see.time() && primary == null && secondary == null) {
                openAge = 0;
                return;
            }
            close();
            open(see.time(), 0);
        }

        /**
         * Per cycle: a sense_body starts a cycle, whose scene shows the latest see. While the clock
         * stands still and no new see came, it is a repeat and the open scene goes on.
         */
        void senseBody(SenseBody body) throws IOException {
            if (cycleOpen && openCycle == body.time()) {
                // The server still runs a step (and executes a body command) on a standing clock:
                // its command log shows these as TIME,STOPPAGE. Each is a cycle of its own.
                report.repeatedSenseBody();
            }
            close();
            if (pending == null) {
                return; // nothing seen yet: actions until the first see are dropped as before
            }
            open(body.time(), openAge + 1);
            report.cycle();
        }

        /** Opens a cycle whose view is {@code age} steps old (steps, not clock time, which may stand still). */
        void open(int cycle, int age) {
            cycleOpen = true;
            openCycle = cycle;
            openAge = age;
        }

        void remember(See see) {
            pending = see;
            pendingObserver = observer;
            pendingWorld = worldModel != null && !perCycle ? worldModel.snapshot(see.time()) : null;
            // the whole line: a server sends one message per datagram, and repeats are whole lines
            int length = lineLength;
            if (lineBytes == null) {
                pendingLength = -1; // a see given as read: its repeats are equal sees (built)
                return;
            }
            if (pendingBytes.length < length) {
                pendingBytes = new byte[Math.max(length, pendingBytes.length * 2)];
            }
            System.arraycopy(lineBytes, lineOffset, pendingBytes, 0, length);
            pendingLength = length;
        }

        void command(PlayerCommand command) {
            if (!command.wellFormed()) {
                report.illFormedCommand();
                return;
            }
            report.command(command.type());
            Action action = command.toAction();
            if (action == null) {
                return;
            }
            if (pending == null || (perCycle && !cycleOpen)) {
                if (!orphanActions) {
                    orphanActions = true;
                    report.drop(DropReason.NO_SEE);
                }
                return;
            }
            if (action.type().worldChanging()) {
                if (primary == null) {
                    primary = action;
                } else {
                    report.extraAction();
                }
            } else if (secondary == null) {
                secondary = action;
            } else {
                report.extraAction();
            }
        }

        /** Ends the pending scene: written when it has an action, else dropped. */
        void close() throws IOException {
            if (pending == null || (perCycle && !cycleOpen)) {
                return;
            }
            int cycle = perCycle ? openCycle : pending.time();
            if (primary == null && secondary == null && !keepUnanswered) {
                report.drop(DropReason.NO_ACTION);
            } else {
                List<Action> actions = primary == null ? secondary == null ? List.of() : List.of(secondary)
                        : secondary == null ? List.of(primary) : List.of(primary, secondary);
                World seenWorld = worldModel == null ? null : perCycle ? worldModel.snapshot(cycle) : pendingWorld;
                Scene scene = new Scene(cycle, pendingObserver, seenObjects(pending, pendingObserver, grid), actions,
                        null, perCycle ? openAge : 0, seenWorld);
                sink.accept(scene);
                report.scene(scene.actionType());
                report.seeAge(scene.seeAge());
            }
            primary = null;
            secondary = null;
            cycleOpen = false;
        }

        void finish() throws IOException {
            close();
            pending = null;
            cycleOpen = false;
        }

        void malformed(long line, String problem) {
            MalformedLine malformed = new MalformedLine(file, line, problem);
            if (strict) {
                throw new LogException(file, line, problem, null);
            }
            report.malformed(malformed);
            warnings.accept(malformed);
        }
    }
}
