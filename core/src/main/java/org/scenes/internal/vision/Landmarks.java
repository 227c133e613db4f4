package org.scenes.internal.vision;

import java.util.ArrayList;
import java.util.List;

/**
 * The 53 flags and 2 goals of the pitch, and its 4 lines (x right, y down, metres), in the order
 * the server describes them in a {@code see}.
 */
public final class Landmarks {
    /** A fixed object; {@code name} is the v7+ short name, e.g. {@code f p r b}. */
    public record Landmark(String name, double x, double y) {
        public boolean goal() {
            return name.charAt(0) == 'g';
        }
    }

    /** A side line: vertical lines have a constant x, horizontal ones a constant y. */
    public record Line(String name, boolean vertical, double at) {
    }

    /** Half the pitch's length and width. */
    public static final double PITCH_HALF_LENGTH = 52.5;
    public static final double PITCH_HALF_WIDTH = 34;

    public static final List<Landmark> ALL = build();
    public static final List<Line> LINES = List.of(new Line("l l", true, -52.5), new Line("l r", true, 52.5),
            new Line("l t", false, -34), new Line("l b", false, 34));

    private Landmarks() {
    }

    private static List<Landmark> build() {
        List<Landmark> all = new ArrayList<>(55);
        all.add(new Landmark("f c", 0, 0));
        all.add(new Landmark("f c t", 0, -34));
        all.add(new Landmark("f c b", 0, 34));
        all.add(new Landmark("f l t", -52.5, -34));
        all.add(new Landmark("f l b", -52.5, 34));
        all.add(new Landmark("f r t", 52.5, -34));
        all.add(new Landmark("f r b", 52.5, 34));
        for (String side : new String[] {"l", "r"}) {
            double sign = side.equals("l") ? -1 : 1;
            all.add(new Landmark("f p " + side + " t", sign * 36, -20.16));
            all.add(new Landmark("f p " + side + " c", sign * 36, 0));
            all.add(new Landmark("f p " + side + " b", sign * 36, 20.16));
            all.add(new Landmark("f g " + side + " t", sign * 52.5, -7.01));
            all.add(new Landmark("f g " + side + " b", sign * 52.5, 7.01));
            all.add(new Landmark("g " + side, sign * 52.5, 0));
        }
        // Boundary flags 5 m outside the pitch.
        for (String edge : new String[] {"t", "b"}) {
            double y = edge.equals("t") ? -39 : 39;
            all.add(new Landmark("f " + edge + " 0", 0, y));
            for (int x = 10; x <= 50; x += 10) {
                all.add(new Landmark("f " + edge + " l " + x, -x, y));
                all.add(new Landmark("f " + edge + " r " + x, x, y));
            }
        }
        for (String edge : new String[] {"l", "r"}) {
            double x = edge.equals("l") ? -57.5 : 57.5;
            all.add(new Landmark("f " + edge + " 0", x, 0));
            for (int y = 10; y <= 30; y += 10) {
                all.add(new Landmark("f " + edge + " t " + y, x, -y));
                all.add(new Landmark("f " + edge + " b " + y, x, y));
            }
        }
        return List.copyOf(all);
    }
}
