package org.scenes.convert;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Objects;
import java.util.function.Consumer;
import java.util.function.LongConsumer;
import org.scenes.protocol.InitReply;
import org.scenes.protocol.InitRequest;
import org.scenes.protocol.Message;
import org.scenes.protocol.MessageParser;
import org.scenes.protocol.PlayerCommand;
import org.scenes.protocol.ProtocolException;
import org.scenes.protocol.See;
import org.scenes.protocol.Unknown;
import org.scenes.protocol.VisualObject;
import org.scenes.scene.Action;
import org.scenes.scene.Grid;
import org.scenes.scene.ObjectKind;
import org.scenes.scene.Observer;
import org.scenes.scene.Relation;
import org.scenes.scene.Scene;
import org.scenes.scene.SeenObject;
import org.scenes.scene.Side;

/**
 * Turns player logs into scenes (the thesis' LogToScenes, rules in docs/conversion.md): a scene is
 * a {@code see} with the actions the player sent after it and before the next different
 * {@code see}; identical repeated {@code see}s (play paused) collapse into one; scenes without
 * action and actions without {@code see} are dropped and counted. The live agent uses
 * {@link #seenObjects} for the same see-to-objects step.
 *
 * <p>Streams: one log line at a time, scenes handed to a {@link SceneSink} as they close.
 * Not thread-safe (it owns a {@link MessageParser}); use one converter per thread.
 */
public final class SceneConverter {
    /** Receives each scene as soon as it is complete. */
    @FunctionalInterface
    public interface SceneSink {
        void accept(Scene scene) throws IOException;
    }

    /** How often (in lines) progress is reported. */
    private static final int PROGRESS_LINES = 4096;

    private final Grid grid;
    private final boolean strict;
    private final Consumer<MalformedLine> warnings;
    private final MessageParser parser = new MessageParser();

    /**
     * @param grid the grid every object's cell is computed with
     * @param strict whether the first malformed line stops the conversion ({@link LogException})
     * @param warnings told of each malformed line when not strict
     */
    public SceneConverter(Grid grid, boolean strict, Consumer<MalformedLine> warnings) {
        this.grid = Objects.requireNonNull(grid, "grid");
        this.strict = strict;
        this.warnings = warnings == null ? line -> { } : warnings;
    }

    public Grid grid() {
        return grid;
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
     * The scene objects of one {@code see} for an observer: names, numbers and marks as parsed,
     * the {@link Relation} to the observer, and each object's cell in {@code grid}.
     */
    public static List<SeenObject> seenObjects(See see, Observer observer, Grid grid) {
        List<VisualObject> objects = see.objects();
        List<SeenObject> seen = new ArrayList<>(objects.size());
        for (VisualObject object : objects) {
            seen.add(new SeenObject(object.kind(), object.name(), object.team(), object.uniformNumber(),
                    object.goalie(), relation(object, observer), object.distance(), object.direction(),
                    object.distanceChange(), object.directionChange(), object.bodyFacing(),
                    object.headFacing(), object.pointingDirection(), object.mark(),
                    grid.cell(object.distance(), object.direction())));
        }
        return seen;
    }

    /**
     * Goals are own or opponent by the observer's side ({@code g r} is own for the right side);
     * players are teammates when their team is the observer's, opponents when another team is
     * readable, unknown otherwise; objects sensed behind (upper case) carry no identity.
     */
    public static Relation relation(VisualObject object, Observer observer) {
        ObjectKind kind = object.kind();
        if (kind == ObjectKind.GOAL) {
            String name = object.name();
            if (object.behind() || name.length() < 3 || observer.side() == null) {
                return Relation.UNKNOWN;
            }
            return name.charAt(2) == observer.side().letter() ? Relation.OWN : Relation.OPPONENT;
        }
        if (kind == ObjectKind.PLAYER) {
            if (object.team().isEmpty() || observer.team().isEmpty()) {
                return Relation.UNKNOWN;
            }
            return object.team().equals(observer.team()) ? Relation.TEAMMATE : Relation.OPPONENT;
        }
        return Relation.NONE;
    }

    /** The state of converting one log. */
    private final class Run {
        final ConversionReport report = new ConversionReport();
        final Path file;
        final SceneSink sink;
        String team = "";
        Side side;
        int uniformNumber;
        Observer observer = Observer.UNKNOWN;

        See pending;
        Observer pendingObserver;
        byte[] pendingBytes = new byte[4096];
        int pendingLength;
        Action primary;
        Action secondary;
        boolean orphanActions;

        Run(Path file, SceneSink sink) {
            this.file = file;
            this.sink = sink;
        }

        void message(LogReader reader) throws IOException {
            if (reader.problem() != null) {
                malformed(reader.line(), reader.problem());
                return;
            }
            if (isRepeat(reader)) {
                // byte-for-byte the see that opened the scene: parsed once already
                report.message();
                report.see();
                report.repeatedSee();
                return;
            }
            Message message;
            try {
                message = parser.parse(reader.buffer(), reader.offset(), reader.length());
            } catch (ProtocolException e) {
                malformed(reader.line(), e.getMessage());
                return;
            }
            report.message();
            if (message instanceof See see) {
                see(see, reader);
            } else if (message instanceof PlayerCommand command) {
                command(command);
            } else if (message instanceof InitRequest init) {
                team = init.team();
                observer = new Observer(team, side, uniformNumber);
            } else if (message instanceof InitReply reply) {
                if (reply.head().equals("reconnect")) {
                    close();
                    pending = null;
                }
                side = reply.side();
                uniformNumber = reply.uniformNumber() > 0 ? reply.uniformNumber() : uniformNumber;
                observer = new Observer(team, side, uniformNumber);
            } else if (message instanceof Unknown unknown) {
                report.unknown(unknown.head());
            }
        }

        boolean isRepeat(LogReader reader) {
            int length = reader.length();
            int offset = reader.offset();
            return pending != null && length == pendingLength
                    && Arrays.equals(pendingBytes, 0, length, reader.buffer(), offset, offset + length);
        }

        void see(See see, LogReader reader) throws IOException {
            report.see();
            int length = reader.length();
            int offset = reader.offset();
            close();
            pending = see;
            pendingObserver = observer;
            if (pendingBytes.length < length) {
                pendingBytes = new byte[Math.max(length, pendingBytes.length * 2)];
            }
            System.arraycopy(reader.buffer(), offset, pendingBytes, 0, length);
            pendingLength = length;
            orphanActions = false;
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
            if (pending == null) {
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
            if (pending == null) {
                return;
            }
            if (primary == null && secondary == null) {
                report.drop(DropReason.NO_ACTION);
            } else {
                List<Action> actions = primary == null ? List.of(secondary)
                        : secondary == null ? List.of(primary) : List.of(primary, secondary);
                Scene scene = new Scene(pending.time(), pendingObserver,
                        seenObjects(pending, pendingObserver, grid), actions);
                sink.accept(scene);
                report.scene(scene.actionType());
            }
            primary = null;
            secondary = null;
        }

        void finish() throws IOException {
            close();
            pending = null;
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
