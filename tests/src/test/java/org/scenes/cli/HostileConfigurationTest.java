package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;

/**
 * The configuration reader on generated JSON-like text: a configuration or a {@link UsageException}
 * naming the file, never another exception (in the cli's package: the reader is package-private).
 */
class HostileConfigurationTest {
    @Provide
    Arbitrary<String> configurations() {
        Arbitrary<String> key = Arbitraries.of("metric", "options", "objectWeights", "actionWeights", "k", "selector",
                "selectorOptions", "transforms", "seed", "crossValidation", "metrc", "");
        Arbitrary<String> value = Arbitraries.of("\"ball-goal\"", "\"cell\"", "3", "-1", "1e400", "\"many\"", "null", "true",
                "[]", "[\"memory\"]", "[1]", "{}", "{\"a\": 1}", "{\"a\": {}}", "\"1/1/1/1/1/1/1/1\"", "\"x/y\"",
                "99999999999999999999", "1.5", "\"\\u0000\"");
        Arbitrary<String> entry = net.jqwik.api.Combinators.combine(key, value).as((k, v) -> "\"" + k + "\": " + v);
        return net.jqwik.api.Combinators.combine(entry.list().ofMaxSize(6), Arbitraries.integers().between(0, 200))
                .as((entries, cut) -> {
                    String text = "{" + String.join(", ", entries) + "}";
                    return cut < 150 ? text : text.substring(0, Math.min(text.length(), cut - 150));
                });
    }

    @Property(tries = 1500)
    void aConfigurationIsReadOrRefusedNamingTheFile(@ForAll("configurations") String text) throws Exception {
        Path file = Files.createTempFile("fuzz", ".json");
        try {
            Files.writeString(file, text, StandardCharsets.UTF_8);
            ConfigFiles.read(file);
        } catch (UsageException expected) {
            assertTrue(expected.getMessage().startsWith(file.toString()), expected.getMessage());
        } finally {
            Files.delete(file);
        }
    }
}
