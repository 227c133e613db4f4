package org.scenes.internal.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.scenes.internal.convert.LogReader;
import org.scenes.internal.proxylog.Direction;
import org.scenes.testing.RequiresSharedData;
import org.scenes.testing.SharedData;

/**
 * Every datagram of the real rcssserver 19 captures in the shared data must parse into a typed
 * message with nothing left over. The one exception is the deliberately bogus {@code (foo 1)}
 * the capture client sent to provoke {@code (error unknown_command)}-style replies: it must come
 * out as {@link Unknown}. Simulated traffic is checked the same way by {@code SimulatedDataTest}
 * in the tests module.
 */
@RequiresSharedData
class RealServerTrafficTest {
    private static final Path DATA = SharedData.resolve("rcssserver19");

    private final MessageParser parser = new MessageParser();

    @ParameterizedTest
    @ValueSource(ints = {5, 7, 9, 15, 19})
    void everyReceivedDatagramIsTypedWithoutLeftovers(int version) throws IOException {
        Map<String, Integer> heads = new TreeMap<>();
        List<String> lines = Files.readAllLines(DATA.resolve("received-v" + version + ".txt"));
        for (String line : lines) {
            Message message = parser.parse(line);
            assertTrue(!(message instanceof Unknown), "unknown message in v" + version + ": " + line);
            assertEquals(List.of(), message.leftovers(), line);
            heads.merge(message.getClass().getSimpleName(), 1, Integer::sum);
        }
        // counts derived with: grep -c '^(see' received-vN.txt (and the same for sense_body, hear)
        assertEquals(version == 19 ? 52 : 70, heads.get("See"));
        assertEquals(100, heads.get("SenseBody"));
        assertEquals(16, heads.get("Hear"));
        assertEquals(1, heads.get("InitReply"));
        if (version >= 7) {
            assertEquals(20, heads.get("Parameters"), "server_param, player_param and 18 player_type");
        }
    }

    @ParameterizedTest
    @ValueSource(ints = {5, 7, 9, 15, 19})
    void everySentDatagramIsTypedWithoutLeftovers(int version) throws IOException {
        List<String> unknown = new ArrayList<>();
        int commands = 0;
        for (String line : Files.readAllLines(DATA.resolve("sent-v" + version + ".txt"))) {
            // "    0.252 k=1 (dash 50)   [no NUL]": time, cycle, datagram, capture note
            String datagram = line.substring(line.indexOf('('));
            int note = datagram.lastIndexOf("   [");
            if (note > 0) {
                datagram = datagram.substring(0, note);
            }
            Message message = parser.parse(datagram);
            if (message instanceof Unknown u) {
                unknown.add(u.text());
                continue;
            }
            assertTrue(message.fromClient(), datagram);
            assertEquals(List.of(), message.leftovers(), datagram);
            commands++;
        }
        assertEquals(List.of("(foo 1)"), unknown);
        assertEquals(119, commands);
    }

    @org.junit.jupiter.api.Test
    void theKrisletCaptureIsTypedWithoutLeftovers() throws IOException {
        int messages = 0;
        try (LogReader reader = LogReader.open(DATA.resolve("krislet-3v3-player1.log.gz"))) {
            while (reader.next()) {
                assertEquals(null, reader.problem(), reader.text());
                Message message = parser.parse(reader.buffer(), reader.offset(), reader.length());
                assertTrue(!(message instanceof Unknown), reader.text());
                assertEquals(List.of(), message.leftovers(), reader.text());
                assertEquals(reader.direction() == Direction.CLIENT_TO_SERVER, message.fromClient(), reader.text());
                messages++;
            }
        }
        // zcat krislet-3v3-player1.log.gz | wc -l
        assertEquals(1577, messages);
    }

    @org.junit.jupiter.api.Test
    void version19SeesCarryTheKickedAndTackleMarks() throws IOException {
        long marked = Files.readAllLines(DATA.resolve("received-v19.txt")).stream()
                .map(parser::parse).filter(See.class::isInstance).map(See.class::cast)
                .flatMap(s -> s.objects().stream()).filter(o -> o.mark() != ' ').count();
        // grep -o "[0-9] [tk])" received-v19.txt | wc -l
        assertEquals(4, marked);
        See first = assertInstanceOf(See.class, parser.parse(Files.readAllLines(DATA.resolve("received-v19.txt")).stream()
                .filter(l -> l.startsWith("(see")).findFirst().orElseThrow()));
        assertTrue(first.objects().stream().anyMatch(VisualObject::goalie));
    }
}
