package org.scenes.internal.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.nio.charset.StandardCharsets;
import java.util.HashMap;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** Short keys (packed in a long) and long ones (compared byte by byte) find exactly what was put. */
class NameTableTest {
    @Test
    void findsWhatWasPutAndNothingElse() {
        NameTable<String> table = new NameTable<>();
        Map<String, String> put = new HashMap<>();
        String[] keys = {"", "a", "f c", "f c t", "f p l t", "f g r b", "sense_bo", "sense_body", "HELIOS_A",
            "HELIOS_AB", "a\0", "\0a", "\u00e9t\u00e9", "f t l 50", "f t l 5", "p"};
        for (String key : keys) {
            byte[] bytes = ("((" + key + ") 1)").getBytes(StandardCharsets.UTF_8);
            table.put(bytes, 2, bytes.length - 4, "value of " + key);
            put.put(key, "value of " + key);
        }
        for (String key : keys) {
            byte[] bytes = ("x" + key + "y").getBytes(StandardCharsets.UTF_8);
            assertEquals(put.get(key), table.get(bytes, 1, bytes.length - 1), key);
        }
        for (String other : new String[] {"b", "f c b", "HELIOS_C", "sense_bodies", "a\0\0", "f t l 5 "}) {
            byte[] bytes = other.getBytes(StandardCharsets.UTF_8);
            assertNull(table.get(bytes, 0, bytes.length), other);
        }
    }

    @Test
    void keepsFindingAfterItEmptiesWhenFull() {
        NameTable<Integer> table = new NameTable<>();
        for (int i = 0; i < 5000; i++) {
            byte[] bytes = ("name " + i).getBytes(StandardCharsets.US_ASCII);
            if (table.get(bytes, 0, bytes.length) == null) {
                table.put(bytes, 0, bytes.length, i);
            }
            assertEquals(i, table.get(bytes, 0, bytes.length));
        }
    }
}
