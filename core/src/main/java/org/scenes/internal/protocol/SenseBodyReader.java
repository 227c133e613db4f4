package org.scenes.internal.protocol;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Reads a {@code (sense_body TIME ...)} after its head: the counters, view mode, stamina, speed
 * and head angle as fields, the other parts ({@code arm}, {@code focus}, {@code tackle},
 * {@code collision}...) as details, anything else as leftovers. Keeps its scratch between
 * messages, as the parser that owns it does.
 */
final class SenseBodyReader {
    /** The sense_body counters, in the order of {@link SenseBody.Counts}. */
    private static final List<String> COUNTERS = List.of("kick", "dash", "turn", "say", "turn_neck", "catch",
            "move", "change_view", "change_focus");

    /** Each counter's place in {@link #COUNTERS}: one look-up per part, not a scan comparing strings. */
    private static final Map<String, Integer> COUNTER_INDEX = counterIndex();

    private final MessageCursor c;
    private final NameTable<String> dottedKeys = new NameTable<>();
    private final int[] senseCounts = new int[COUNTERS.size()];
    private final String[] detailKeys = new String[16];
    private final String[] detailValues = new String[16];
    private int detailCount;
    private byte[] keyScratch = new byte[64];

    private static Map<String, Integer> counterIndex() {
        Map<String, Integer> index = new HashMap<>();
        for (int i = 0; i < COUNTERS.size(); i++) {
            index.put(COUNTERS.get(i), i);
        }
        return index;
    }

    SenseBodyReader(MessageCursor cursor) {
        this.c = cursor;
    }

    SenseBody read() {
        int time = c.integer("the time of sense_body");
        String quality = "";
        String width = "";
        double nan = Double.NaN;
        double stamina = nan;
        double effort = nan;
        double capacity = nan;
        double speed = nan;
        double speedDirection = nan;
        double headAngle = nan;
        int[] counts = senseCounts;
        Arrays.fill(counts, -1);
        detailCount = 0;
        List<String> leftovers = List.of();
        while (true) {
            c.skipSpace();
            if (c.buf[c.pos] == ')') {
                break;
            }
            int elementStart = c.pos;
            boolean understood = c.buf[c.pos] == '(';
            if (understood) {
                c.pos++;
                c.skipSpace();
                int keyStart = c.pos;
                int keyEnd = c.atomEnd();
                String key = NameTable.string(c.words, c.buf, keyStart, keyEnd);
                c.pos = keyEnd;
                int counter = COUNTER_INDEX.getOrDefault(key, -1);
                if (counter >= 0) {
                    understood = c.numbers() == 1 && c.numbers[0] == (int) c.numbers[0] && c.numbers[0] >= 0;
                    if (understood) {
                        counts[counter] = (int) c.numbers[0];
                    }
                } else {
                    switch (key) {
                        case "view_mode" -> {
                            quality = c.word();
                            width = c.word();
                        }
                        case "stamina" -> {
                            int n = c.numbers();
                            stamina = n > 0 ? c.numbers[0] : nan;
                            effort = n > 1 ? c.numbers[1] : nan;
                            capacity = n > 2 ? c.numbers[2] : nan;
                            understood = n >= 2 && n <= 3;
                        }
                        case "speed" -> {
                            int n = c.numbers();
                            speed = n > 0 ? c.numbers[0] : nan;
                            speedDirection = n > 1 ? c.numbers[1] : nan;
                            understood = n >= 1 && n <= 2;
                        }
                        case "head_angle" -> {
                            understood = c.numbers() == 1;
                            headAngle = c.numbers[0];
                        }
                        case "arm", "focus", "tackle", "foul" -> understood = subfields(keyStart);
                        case "collision", "focus_point" -> {
                            c.skipSpace();
                            int valueStart = c.pos;
                            c.skipToClose();
                            detail(key, valueStart, c.pos);
                        }
                        default -> understood = false;
                    }
                }
                c.skipSpace();
                understood &= c.buf[c.pos] == ')';
            }
            if (understood) {
                c.pos++;
            } else {
                c.pos = elementStart;
                c.skipElement();
                if (leftovers.isEmpty()) {
                    leftovers = new ArrayList<>(2);
                }
                leftovers.add(c.text(elementStart, c.pos));
            }
        }
        boolean anyCount = false;
        for (int count : counts) {
            anyCount |= count >= 0;
        }
        SenseBody.Counts typedCounts = !anyCount ? SenseBody.Counts.NONE
                : new SenseBody.Counts(counts[0], counts[1], counts[2], counts[3], counts[4], counts[5], counts[6],
                        counts[7], counts[8]);
        return new SenseBody(time, quality, width, stamina, effort, capacity, speed, speedDirection,
                headAngle, typedCounts, details(), leftovers);
    }

    /**
     * {@code (arm (movable 0) (expires 0) (target 0 0) (count 0))}: each part as {@code arm.movable}...
     * Keys are cached by the bytes from the parent's name to the part's name, values by their bytes,
     * so a sense_body allocates little beyond its record.
     */
    private boolean subfields(int parentStart) {
        while (true) {
            c.skipSpace();
            if (c.buf[c.pos] == ')') {
                return true;
            }
            if (c.buf[c.pos] != '(') {
                return false;
            }
            c.pos++;
            c.skipSpace();
            int keyStart = c.pos;
            int keyEnd = c.atomEnd();
            String key = dottedKey(parentStart, keyStart, keyEnd);
            c.pos = keyEnd;
            c.skipSpace();
            int valueStart = c.pos;
            c.skipToClose();
            detail(key, valueStart, c.pos);
            c.pos++;
        }
    }

    /** "arm" and "target" become the cached "arm.target" (cached by its bytes, built once). */
    private String dottedKey(int parentStart, int keyStart, int keyEnd) {
        int parentEnd = parentStart;
        while (parentEnd < c.end && !MessageCursor.isSpace(c.buf[parentEnd]) && c.buf[parentEnd] != '(' && c.buf[parentEnd] != ')') {
            parentEnd++;
        }
        int length = (parentEnd - parentStart) + 1 + (keyEnd - keyStart);
        if (keyScratch.length < length) {
            keyScratch = new byte[length * 2];
        }
        System.arraycopy(c.buf, parentStart, keyScratch, 0, parentEnd - parentStart);
        keyScratch[parentEnd - parentStart] = '.';
        System.arraycopy(c.buf, keyStart, keyScratch, parentEnd - parentStart + 1, keyEnd - keyStart);
        return NameTable.string(dottedKeys, keyScratch, 0, length);
    }

    private void detail(String key, int valueStart, int valueEnd) {
        while (valueEnd > valueStart && MessageCursor.isSpace(c.buf[valueEnd - 1])) {
            valueEnd--;
        }
        for (int i = 0; i < detailCount; i++) {
            if (detailKeys[i].equals(key)) { // sent twice: the last one counts
                detailValues[i] = NameTable.string(c.words, c.buf, valueStart, valueEnd);
                return;
            }
        }
        if (detailCount < detailKeys.length) {
            detailKeys[detailCount] = key;
            detailValues[detailCount] = NameTable.string(c.words, c.buf, valueStart, valueEnd);
            detailCount++;
        }
    }

    @SuppressWarnings("unchecked")
    private Map<String, String> details() {
        if (detailCount == 0) {
            return Map.of();
        }
        Map.Entry<String, String>[] entries = new Map.Entry[detailCount];
        for (int i = 0; i < detailCount; i++) {
            entries[i] = Map.entry(detailKeys[i], detailValues[i]);
        }
        return Map.ofEntries(entries);
    }
}
