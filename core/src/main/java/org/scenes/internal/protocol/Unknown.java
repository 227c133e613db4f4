package org.scenes.internal.protocol;

import java.util.List;

/** A balanced message whose head the parser does not know; kept whole so nothing is lost. */
public record Unknown(String head, String text) implements Message {
    @Override
    public List<String> leftovers() {
        return List.of(text);
    }
}
