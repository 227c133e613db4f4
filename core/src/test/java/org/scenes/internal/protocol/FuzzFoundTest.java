package org.scenes.internal.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Inputs fuzzing found (docs/reliability.md), kept as plain regression tests of the parser. */
class FuzzFoundTest {
    /** Jazzer's first crash: a quote inside an atom hid parentheses from the balance check, not from the parser. */
    private static final String QUOTE_INSIDE_ATOM = "KHNlZSAxMiAoKGIpIDEuNSAtMyAwLjEgJTAuMikgKCjIyMjIyMjIyMjIyMjIyMjIAAAAAAAAIADIyMjIy"
            + "MjIyMjIKSh1YCkooikobCkoYCkAAAAAAFouMikgKChnIHIpIDMwNiAxMCkgcCI7YShyKENAZXRvbiIgMyBnb2FsaWUwMij/KSj/byko/yko////"
            + "+ykooiko/yko/28pKP8pKKIpKLRsKShgKSj/KSj/byko/ykoWmzgzN+dmiB0KSA0MCAtMjApKQ==";

    @Test
    void aQuoteInsideAnAtomIsAnOrdinaryByteForTheBalanceCheckToo() {
        byte[] crash = Base64.getDecoder().decode(QUOTE_INSIDE_ATOM);
        // it threw ArrayIndexOutOfBoundsException; now the unbalanced message is said to be one
        assertThrows(ProtocolException.class, () -> new MessageParser().parseAll(crash, 0, crash.length, m -> { }));

        byte[] balanced = "(see 3 ((b) 1 2) (x\"y(z)) ((g r) 30 0))".getBytes(StandardCharsets.US_ASCII);
        List<Message> messages = new ArrayList<>();
        new MessageParser().parseAll(balanced, 0, balanced.length, messages::add);
        assertEquals(1, messages.size());
        assertEquals(2, ((See) messages.get(0)).objects().size());
    }
}
