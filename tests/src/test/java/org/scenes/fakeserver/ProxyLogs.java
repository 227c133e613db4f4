package org.scenes.fakeserver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HexFormat;
import java.util.List;
import org.scenes.internal.proxylog.Direction;
import org.scenes.internal.proxylog.ProxyLogLine;

/** A native proxy log read back, for assertions. */
record ProxyLogs(List<ProxyLogLine> lines, List<String> comments) {
    static ProxyLogs read(Path file) throws IOException {
        List<String> text = Files.readAllLines(file, StandardCharsets.UTF_8);
        assertEquals(ProxyLogLine.HEADER, text.get(0), file + " header");
        List<ProxyLogLine> lines = new ArrayList<>();
        List<String> comments = new ArrayList<>();
        for (String line : text.subList(1, text.size())) {
            if (ProxyLogLine.isComment(line)) {
                comments.add(line);
            } else {
                lines.add(ProxyLogLine.parse(line));
            }
        }
        return new ProxyLogs(lines, comments);
    }

    List<byte[]> messages(Direction direction) {
        return lines.stream().filter(l -> l.direction() == direction).map(ProxyLogLine::message).toList();
    }

    void assertTimesNeverGoBack() {
        for (int i = 1; i < lines.size(); i++) {
            assertTrue(lines.get(i).micros() >= lines.get(i - 1).micros(), "time goes back at message " + i);
        }
    }

    String lastComment() {
        return comments.get(comments.size() - 1);
    }

    /** The datagram as the log holds it: without trailing NUL padding. */
    static byte[] unpadded(byte[] datagram) {
        int end = datagram.length;
        while (end > 0 && datagram[end - 1] == 0) {
            end--;
        }
        return Arrays.copyOf(datagram, end);
    }

    static List<byte[]> unpadded(List<byte[]> datagrams) {
        return datagrams.stream().map(ProxyLogs::unpadded).toList();
    }

    /** Readable form of a datagram list, so a failing assertion shows where lists differ. */
    static List<String> show(List<byte[]> datagrams) {
        return datagrams.stream().map(d -> d.length < 120 ? HexFormat.of().formatHex(d)
                : d.length + " bytes, hash " + Arrays.hashCode(d)).toList();
    }

    static void assertSameDatagrams(List<byte[]> expected, List<byte[]> actual, String what) {
        assertEquals(show(expected), show(actual), what);
        for (int i = 0; i < expected.size(); i++) {
            assertTrue(Arrays.equals(expected.get(i), actual.get(i)), what + ": datagram " + i + " differs");
        }
    }

    /** True if {@code part} appears in {@code whole} in order (not necessarily adjacent). */
    static boolean isSubsequence(List<byte[]> part, List<byte[]> whole) {
        int next = 0;
        for (byte[] datagram : whole) {
            if (next < part.size() && Arrays.equals(part.get(next), datagram)) {
                next++;
            }
        }
        return next == part.size();
    }
}
