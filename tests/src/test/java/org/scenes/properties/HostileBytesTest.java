package org.scenes.properties;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import org.scenes.api.Grid;
import org.scenes.internal.convert.LogException;
import org.scenes.internal.convert.LogReader;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.ProtocolException;
import org.scenes.internal.scene.SceneFileException;
import org.scenes.internal.scene.SceneFileReader;

/**
 * Generated hostile input for every reader (the fuzzing fallback where Jazzer does not run, see
 * docs/reliability.md): bytes near the protocol's grammar and plain random bytes. The allowed
 * outcomes are a parsed result or the reader's documented error, never another exception.
 */
class HostileBytesTest {
    private static final List<String> TOKENS = List.of("(", ")", " ", "see", "sense_body", "hear", "init", "dash",
            "turn", "kick", "(b)", "((b)", "((g r)", "((p \"T\" 1)", "((f c)", "0", "-1", "1e309", "NaN", "3.5", "\"",
            "\\", "\0", "\n", "\u00ff", "server_param", "player_type", "(ok synch_see)", "error", "l", "r", "999999999999");

    @Provide
    Arbitrary<byte[]> nearProtocol() {
        Arbitrary<byte[]> tokens = Arbitraries.of(TOKENS).list().ofMaxSize(60)
                .map(list -> String.join("", list).getBytes(StandardCharsets.UTF_8));
        Arbitrary<byte[]> random = Arbitraries.bytes().array(byte[].class).ofMaxSize(300);
        return Arbitraries.oneOf(tokens, random);
    }

    @Property(tries = 3000)
    void theParserReturnsMessagesOrAProtocolException(@ForAll("nearProtocol") byte[] bytes) {
        MessageParser parser = new MessageParser();
        try {
            parser.parseAll(bytes, 0, bytes.length, message -> assertTrue(message != null));
        } catch (ProtocolException expected) {
            assertTrue(expected.getMessage() != null && !expected.getMessage().isEmpty());
        }
    }

    @Provide
    Arbitrary<byte[]> logs() {
        Arbitrary<String> prefix = Arbitraries.of("", "#scenes-proxy-log 1\n", "1.5 c2s ", "1700000000.5 client->server 4000 ",
                "(init l 1 before_kick_off)\n");
        Arbitrary<String> line = Arbitraries.oneOf(
                Arbitraries.of(TOKENS).list().ofMaxSize(30).map(l -> String.join("", l)),
                Arbitraries.of("0.1 s2c (see 0 ((b) 1 2))", "0.2 c2s (dash 50)", "(see 1 ((b) 1 2))", "(kick 100 0)",
                        "1700000000.5 server->client 4000 (see 3 ((b) 2 3))", "0.3 s2c \\x00\\q", "# comment"));
        return Combinators.combine(prefix, line.list().ofMaxSize(20))
                .as((p, lines) -> (p + String.join("\n", lines)).getBytes(StandardCharsets.UTF_8));
    }

    @Property(tries = 1500)
    void everyLogFormatReadsToTheEndOrGivesALogException(@ForAll("logs") byte[] log) throws IOException {
        try (LogReader reader = LogReader.read(Path.of("fuzz.log"), new ByteArrayInputStream(log))) {
            while (reader.next()) {
                assertTrue(reader.length() >= 0 && reader.offset() >= 0);
            }
        } catch (LogException expected) {
            assertTrue(expected.getMessage().startsWith("fuzz.log"), expected.getMessage());
        }
    }

    @Property(tries = 400)
    void conversionOfAnyLogEndsInAReportOrALogException(@ForAll("logs") byte[] log) throws IOException {
        Path file = Files.createTempFile("fuzz", ".lsf");
        try {
            Files.write(file, log);
            SceneConverter.with(Grid.DEFAULT).build().convert(file, scene -> { });
        } catch (LogException expected) {
            assertTrue(expected.getMessage().startsWith(file.toString()), expected.getMessage());
        } finally {
            Files.delete(file);
        }
    }

    /** A valid scene file of three scenes as the writer makes it: what the damage starts from. */
    private static byte[] validSceneFile() {
        try {
            Path file = Files.createTempFile("valid", ".json");
            org.scenes.api.Observer observer = new org.scenes.api.Observer("T", org.scenes.api.Side.LEFT, 1);
            try (org.scenes.internal.scene.SceneFileWriter writer = org.scenes.internal.scene.SceneFileWriter.create(file,
                    org.scenes.internal.scene.SceneFileHeader.of(Grid.DEFAULT, new org.scenes.internal.scene.SceneSource("x", observer)))) {
                for (int i = 0; i < 3; i++) {
                    writer.write(new org.scenes.api.Scene(i, observer, List.of(org.scenes.api.SeenObject.simple(
                            org.scenes.api.ObjectKind.BALL, "b", org.scenes.api.Relation.NONE, 1.5 + i, 3, Grid.DEFAULT)),
                            List.of(org.scenes.api.Action.dash(50))));
                }
                writer.commit();
            }
            byte[] bytes = Files.readAllBytes(file);
            Files.delete(file);
            return bytes;
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    @Provide
    Arbitrary<byte[]> sceneFiles() {
        byte[] valid = validSceneFile();
        // a valid file with bytes replaced, cut short or both
        return Combinators.combine(Arbitraries.integers().between(0, valid.length),
                        Arbitraries.integers().between(0, valid.length - 1).list().ofMaxSize(6),
                        Arbitraries.bytes().list().ofMinSize(6).ofMaxSize(6))
                .as((cut, positions, replacements) -> {
                    byte[] bytes = java.util.Arrays.copyOf(valid, cut);
                    for (int i = 0; i < positions.size(); i++) {
                        if (positions.get(i) < bytes.length) {
                            bytes[positions.get(i)] = replacements.get(i);
                        }
                    }
                    return bytes;
                });
    }

    @Property(tries = 1500)
    void aDamagedSceneFileGivesScenesOrASceneFileException(@ForAll("sceneFiles") byte[] content) throws IOException {
        Path file = Files.createTempFile("fuzz", ".json");
        try {
            Files.write(file, content);
            SceneFileReader.read(file);
        } catch (SceneFileException expected) {
            assertTrue(expected.getMessage().startsWith(file.toString()), expected.getMessage());
        } finally {
            Files.delete(file);
        }
    }
}
