package org.scenes.internal.protocol;

import java.nio.charset.StandardCharsets;
import org.scenes.api.ObjectKind;

/** A landmark, ball or upper-case object name, normalised once per distinct spelling. */
record ObjectName(ObjectKind kind, String name) {
    static ObjectName of(byte[] buf, int nameStart, int nameEnd) {
        StringBuilder name = new StringBuilder(12);
        ObjectKind kind = null;
        int p = nameStart;
        boolean first = true;
        boolean upper = false;
        while (p < nameEnd) {
            while (p < nameEnd && MessageCursor.isSpace(buf[p])) {
                p++;
            }
            int wordStart = p;
            while (p < nameEnd && !MessageCursor.isSpace(buf[p])) {
                p++;
            }
            if (wordStart == p) {
                break;
            }
            String word = new String(buf, wordStart, p - wordStart, StandardCharsets.UTF_8);
            if (first) {
                String letter = switch (word) {
                    case "b", "ball" -> "b";
                    case "B", "Ball" -> "B";
                    case "g", "goal" -> "g";
                    case "G", "Goal" -> "G";
                    case "f", "flag" -> "f";
                    case "F", "Flag" -> "F";
                    case "l", "line" -> "l";
                    default -> null;
                };
                if (letter == null) {
                    return null;
                }
                upper = Character.isUpperCase(letter.charAt(0));
                kind = switch (Character.toLowerCase(letter.charAt(0))) {
                    case 'b' -> ObjectKind.BALL;
                    case 'g' -> ObjectKind.GOAL;
                    case 'f' -> ObjectKind.FLAG;
                    default -> ObjectKind.LINE;
                };
                name.append(letter);
                first = false;
            } else {
                if (upper || kind == ObjectKind.BALL) {
                    return null;
                }
                name.append(' ').append(word);
            }
        }
        return kind == null ? null : new ObjectName(kind, name.toString());
    }
}
