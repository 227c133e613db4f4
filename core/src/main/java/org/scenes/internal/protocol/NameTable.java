package org.scenes.internal.protocol;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * Maps byte ranges to values without allocating on a hit: the same flag names, team names and
 * heads repeat in every message, so each is decoded once. Open addressing; emptied when it fills
 * up, which bounds memory on hostile input.
 */
final class NameTable<V> {
    private static final int CAPACITY = 1024;

    private final byte[][] keys = new byte[CAPACITY][];
    private final Object[] values = new Object[CAPACITY];
    private int size;

    @SuppressWarnings("unchecked")
    V get(byte[] bytes, int start, int end) {
        int slot = hash(bytes, start, end) & (CAPACITY - 1);
        while (keys[slot] != null) {
            if (Arrays.equals(keys[slot], 0, keys[slot].length, bytes, start, end)) {
                return (V) values[slot];
            }
            slot = (slot + 1) & (CAPACITY - 1);
        }
        return null;
    }

    void put(byte[] bytes, int start, int end, V value) {
        if (size >= CAPACITY / 2) {
            Arrays.fill(keys, null);
            Arrays.fill(values, null);
            size = 0;
        }
        int slot = hash(bytes, start, end) & (CAPACITY - 1);
        while (keys[slot] != null) {
            slot = (slot + 1) & (CAPACITY - 1);
        }
        keys[slot] = Arrays.copyOfRange(bytes, start, end);
        values[slot] = value;
        size++;
    }

    /** The cached string for the bytes, decoding them as UTF-8 the first time. */
    static String string(NameTable<String> table, byte[] bytes, int start, int end) {
        String value = table.get(bytes, start, end);
        if (value == null) {
            value = new String(bytes, start, end - start, StandardCharsets.UTF_8);
            table.put(bytes, start, end, value);
        }
        return value;
    }

    private static int hash(byte[] bytes, int start, int end) {
        int hash = 0x811c9dc5;
        for (int i = start; i < end; i++) {
            hash = (hash ^ bytes[i]) * 0x01000193;
        }
        return hash ^ (hash >>> 16);
    }
}
