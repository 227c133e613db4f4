package org.scenes.internal.files;

import java.util.regex.Pattern;

/** Jackson's parse errors in the user's words: what is wrong, without the library's switches to flip. */
public final class JsonErrors {
    /** "... : enable `JsonReadFeature.X` to allow" and the like name settings only a programmer has. */
    private static final Pattern LIBRARY_HINT = Pattern.compile("[:;,]?\\s*(\\(?(enable|disable)\\s+`?[A-Za-z_.]+`?"
            + "( to (allow|accept)[^)]*)?\\)?)");

    private JsonErrors() {
    }

    /** The message without hints about library features, on one line. */
    public static String plain(String originalMessage) {
        if (originalMessage == null) {
            return "malformed JSON";
        }
        String text = LIBRARY_HINT.matcher(originalMessage).replaceAll("");
        return text.replaceAll("\\s*\\R\\s*", " ").strip();
    }
}
