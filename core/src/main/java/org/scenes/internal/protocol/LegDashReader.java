package org.scenes.internal.protocol;

import java.util.Arrays;

/** Reads rcssserver 19's two-leg dash, rare next to the plain one, for {@link MessageParser}'s commands. */
final class LegDashReader {
    private LegDashReader() {
    }

    /**
     * rcssserver 19's two-leg dash, {@code (dash (l POWER DIR) (r POWER DIR))}, either leg alone or
     * both in any order. Kept in {@code text} as the server got it (single spaces); {@code first} and
     * {@code second} are the mean power and direction of the legs sent, the plain dash closest to it.
     */
    static PlayerCommand read(MessageCursor c, int count, int[] argStart, int[] argEnd) {
        boolean wellFormed = count == 1 || count == 2;
        double powerSum = 0;
        double directionSum = 0;
        int legs = 0;
        boolean left = false;
        boolean right = false;
        StringBuilder text = new StringBuilder(24);
        int arguments = Math.min(count, argStart.length);
        int[] starts = Arrays.copyOf(argStart, arguments);
        int[] ends = Arrays.copyOf(argEnd, arguments);
        int saved = c.pos;
        for (int i = 0; i < arguments && wellFormed; i++) {
            if (c.buf[starts[i]] != '(') {
                wellFormed = false;
                break;
            }
            c.pos = starts[i] + 1;
            String leg = c.word();
            boolean isLeft = leg.equals("l");
            if (!(isLeft || leg.equals("r")) || (isLeft ? left : right)) {
                wellFormed = false;
                break;
            }
            if (isLeft) {
                left = true;
            } else {
                right = true;
            }
            if (text.length() > 0) {
                text.append(' ');
            }
            text.append('(').append(leg);
            int listEnd = ends[i] - 1;
            int found = 0;
            double power = Double.NaN;
            double direction = Double.NaN;
            while (true) {
                c.skipSpace();
                if (c.pos >= listEnd) {
                    break;
                }
                int tokenEnd = c.atomEnd();
                double value = c.number(c.pos, tokenEnd);
                if (Double.isNaN(value) || found == 2) {
                    found = -1;
                    break;
                }
                text.append(' ').append(c.text(c.pos, tokenEnd));
                c.pos = tokenEnd;
                if (found == 0) {
                    power = value;
                } else {
                    direction = value;
                }
                found++;
            }
            if (found != 2) {
                wellFormed = false;
                break;
            }
            text.append(')');
            powerSum += power;
            directionSum += direction;
            legs++;
        }
        c.pos = saved;
        if (!wellFormed || legs == 0) {
            return new PlayerCommand(CommandType.DASH, Double.NaN, Double.NaN, "", false);
        }
        return new PlayerCommand(CommandType.DASH, powerSum / legs, directionSum / legs, text.toString(), true);
    }
}
