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
    /** The bytes of each key of up to eight bytes, packed by {@link #pack}. */
    private final long[] packedKeys = new long[CAPACITY];
    private int size;

    @SuppressWarnings("unchecked")
    V get(byte[] bytes, int start, int end) {
        int length = end - start;
        if (length <= Long.BYTES) {
            // short keys (flag names, heads, most team names) compare as one long, no byte loop
            long packed = pack(bytes, start, end);
            int slot = hash(packed, length) & (CAPACITY - 1);
            while (keys[slot] != null) {
                if (packedKeys[slot] == packed && keys[slot].length == length) {
                    return (V) values[slot];
                }
                slot = (slot + 1) & (CAPACITY - 1);
            }
            return null;
        }
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
        int length = end - start;
        long packed = length <= Long.BYTES ? pack(bytes, start, end) : 0;
        int slot = (length <= Long.BYTES ? hash(packed, length) : hash(bytes, start, end)) & (CAPACITY - 1);
        while (keys[slot] != null) {
            slot = (slot + 1) & (CAPACITY - 1);
        }
        keys[slot] = Arrays.copyOfRange(bytes, start, end);
        packedKeys[slot] = packed;
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

    /** Up to eight bytes in one long, the first in the lowest byte. */
    private static long pack(byte[] bytes, int start, int end) {
        long packed = 0;
        for (int i = end - 1; i >= start; i--) {
            packed = packed << 8 | (bytes[i] & 0xFF);
        }
        return packed;
    }

    private static int hash(long packed, int length) {
        long mixed = (packed ^ length) * 0x9E3779B97F4A7C15L;
        return (int) (mixed ^ (mixed >>> 32));
    }

    private static int hash(byte[] bytes, int start, int end) {
        int hash = 0x811c9dc5;
        for (int i = start; i < end; i++) {
            hash = (hash ^ bytes[i]) * 0x01000193;
        }
        return hash ^ (hash >>> 16);
    }
}
