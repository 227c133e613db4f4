package org.scenes.internal.convert;

import java.util.ArrayList;
import java.util.Collections;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.scenes.api.ActionType;
import org.scenes.internal.protocol.CommandType;

/**
 * What a conversion did, summed over every log it read: messages by kind, scenes written, scenes
 * dropped by {@link DropReason}, commands and kept actions by type, unknown messages by head and
 * malformed lines. Not thread-safe; {@link #add} merges reports of separate conversions.
 */
public final class ConversionReport {
    /** Malformed lines remembered with their place; further ones are only counted. */
    public static final int MALFORMED_KEPT = 100;

    private long logs;
    private long lines;
    private long bytes;
    private long messages;
    private long sees;
    private long repeatedSees;
    private long scenes;
    private long extraActions;
    private long illFormedCommands;
    private long malformed;
    private long perCycleLogs;
    private long cycles;
    private long repeatedSenseBodies;
    private final Map<Integer, Long> seeAges = new TreeMap<>();
    private final Map<DropReason, Long> dropped = new EnumMap<>(DropReason.class);
    private final Map<CommandType, Long> commands = new EnumMap<>(CommandType.class);
    /** Scenes by primary action type's ordinal: counted once a scene, without a boxed map entry. */
    private final long[] actions = new long[ActionType.values().length];
    private final Map<String, Long> unknown = new TreeMap<>();
    private final List<MalformedLine> malformedLines = new ArrayList<>();

    void log(long lineCount, long byteCount) {
        logs++;
        lines += lineCount;
        bytes += byteCount;
    }

    void message() {
        messages++;
    }

    void see() {
        sees++;
    }

    void repeatedSee() {
        repeatedSees++;
    }

    void scene(ActionType primary) {
        scenes++;
        actions[primary.ordinal()]++;
    }

    void perCycle() {
        perCycleLogs++;
    }

    void cycle() {
        cycles++;
    }

    void repeatedSenseBody() {
        repeatedSenseBodies++;
    }

    void seeAge(int age) {
        seeAges.merge(age, 1L, Long::sum);
    }

    void drop(DropReason reason) {
        dropped.merge(reason, 1L, Long::sum);
    }

    void command(CommandType type) {
        commands.merge(type, 1L, Long::sum);
    }

    void illFormedCommand() {
        illFormedCommands++;
    }

    void extraAction() {
        extraActions++;
    }

    void unknown(String head) {
        unknown.merge(head, 1L, Long::sum);
    }

    void malformed(MalformedLine line) {
        malformed++;
        if (malformedLines.size() < MALFORMED_KEPT) {
            malformedLines.add(line);
        }
    }

    /** Adds another report's counts to this one. */
    public void add(ConversionReport other) {
        logs += other.logs;
        lines += other.lines;
        bytes += other.bytes;
        messages += other.messages;
        sees += other.sees;
        repeatedSees += other.repeatedSees;
        scenes += other.scenes;
        extraActions += other.extraActions;
        illFormedCommands += other.illFormedCommands;
        malformed += other.malformed;
        perCycleLogs += other.perCycleLogs;
        cycles += other.cycles;
        repeatedSenseBodies += other.repeatedSenseBodies;
        other.seeAges.forEach((k, v) -> seeAges.merge(k, v, Long::sum));
        other.dropped.forEach((k, v) -> dropped.merge(k, v, Long::sum));
        other.commands.forEach((k, v) -> commands.merge(k, v, Long::sum));
        for (int i = 0; i < actions.length; i++) {
            actions[i] += other.actions[i];
        }
        other.unknown.forEach((k, v) -> unknown.merge(k, v, Long::sum));
        for (MalformedLine line : other.malformedLines) {
            if (malformedLines.size() < MALFORMED_KEPT) {
                malformedLines.add(line);
            }
        }
    }

    public long logs() {
        return logs;
    }

    public long lines() {
        return lines;
    }

    /** Uncompressed bytes of log text read. */
    public long bytes() {
        return bytes;
    }

    /** Messages parsed (every non-blank, non-comment line that parsed). */
    public long messages() {
        return messages;
    }

    /** {@code see} messages read, repeats included. */
    public long sees() {
        return sees;
    }

    /** {@code see} messages identical to the one before, collapsed into it. */
    public long repeatedSees() {
        return repeatedSees;
    }

    /** Logs converted a scene per cycle (the server confirmed synchronous vision, or pairing was cycle). */
    public long perCycleLogs() {
        return perCycleLogs;
    }

    /** Per cycle: cycles opened by a {@code sense_body} after the first {@code see}. */
    public long cycles() {
        return cycles;
    }

    /** Per cycle: {@code sense_body}s of a standing clock (each still a cycle: the server runs the step). */
    public long repeatedSenseBodies() {
        return repeatedSenseBodies;
    }

    /** Scenes written by the age of the {@code see} they show (0: seen in the cycle they acted). */
    public Map<Integer, Long> seeAges() {
        return Collections.unmodifiableMap(seeAges);
    }

    public long scenes() {
        return scenes;
    }

    public long dropped(DropReason reason) {
        return dropped.getOrDefault(reason, 0L);
    }

    public long droppedTotal() {
        return dropped.values().stream().mapToLong(Long::longValue).sum();
    }

    /** Well-formed player commands read, by type. */
    public Map<CommandType, Long> commands() {
        return Collections.unmodifiableMap(commands);
    }

    public long commands(CommandType type) {
        return commands.getOrDefault(type, 0L);
    }

    /** Primary actions of the scenes written, by type. */
    public Map<ActionType, Long> actions() {
        Map<ActionType, Long> counted = new EnumMap<>(ActionType.class);
        for (ActionType type : ActionType.values()) {
            if (actions[type.ordinal()] > 0) {
                counted.put(type, actions[type.ordinal()]);
            }
        }
        return Collections.unmodifiableMap(counted);
    }

    /** Scene actions sent after a scene already had its primary (and secondary) action. */
    public long extraActions() {
        return extraActions;
    }

    /** Commands of a form the server rejects, e.g. {@code (dash)}; never scene actions. */
    public long illFormedCommands() {
        return illFormedCommands;
    }

    /** Messages with an unknown head, by head. */
    public Map<String, Long> unknown() {
        return Collections.unmodifiableMap(unknown);
    }

    public long malformed() {
        return malformed;
    }

    /** The first {@value #MALFORMED_KEPT} malformed lines with file and line. */
    public List<MalformedLine> malformedLines() {
        return Collections.unmodifiableList(malformedLines);
    }
}
