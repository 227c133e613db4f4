package org.scenes.internal.world;

import java.util.HashMap;
import java.util.Map;
import org.scenes.api.ObjectKind;
import org.scenes.internal.protocol.See;
import org.scenes.internal.protocol.VisualObject;
import org.scenes.internal.vision.Landmarks;

/**
 * Where a player stands and looks, from one {@code see}, in server coordinates (x right, y down,
 * directions in degrees from +x towards +y). The server's noise is rounding: directions to whole
 * degrees, landmark distances in the log domain ({@code quantize_step_l}, 0.5 % of the distance)
 * then to 0.1 m. So:
 *
 * <ol>
 *   <li>the head's direction comes from the seen line when there is one (the angle between view
 *   and line, exact to half a degree; from inside the pitch the view always meets a line), the
 *   candidate nearest to a first guess: the rotation that best lays the seen flags onto their known
 *   positions (two or more flags), else the caller's predicted head;</li>
 *   <li>the position is the mean of what each seen flag and goal says (its known position minus
 *   the seen offset turned by the head), weighted by the inverse square distance, as a flag's
 *   error grows with its distance.</li>
 * </ol>
 */
final class Localisation {
    private static final Map<String, Landmarks.Landmark> LANDMARKS = new HashMap<>();
    private static final Map<String, Landmarks.Line> LINES = new HashMap<>();

    static {
        for (Landmarks.Landmark landmark : Landmarks.ALL) {
            LANDMARKS.put(landmark.name(), landmark);
        }
        for (Landmarks.Line line : Landmarks.LINES) {
            LINES.put(line.name(), line);
        }
    }

    /** A pose: position and the head's direction (body + neck), server frame. */
    record Pose(double x, double y, double head) {
    }

    private Localisation() {
    }

    /**
     * The pose the see shows, or null when it shows too little (no head direction: no line and
     * fewer than two flags without {@code predictedHead}; no position: no flag with a distance).
     *
     * @param predictedHead the head direction carried on from before, NaN when not known
     */
    static Pose locate(See see, double predictedHead) {
        double flagHead = flagRotation(see);
        double hint = !Double.isNaN(flagHead) ? flagHead : predictedHead;
        double head = lineHead(see, hint);
        if (Double.isNaN(head)) {
            head = hint;
        }
        if (Double.isNaN(head)) {
            return null;
        }
        double sumW = 0;
        double sumX = 0;
        double sumY = 0;
        for (VisualObject object : see.objects()) {
            Landmarks.Landmark landmark = landmark(object);
            if (landmark == null) {
                continue;
            }
            double d = object.distance();
            double a = Math.toRadians(head + object.direction());
            double w = 1 / Math.max(d * d, 1);
            sumX += w * (landmark.x() - d * Math.cos(a));
            sumY += w * (landmark.y() - d * Math.sin(a));
            sumW += w;
        }
        if (sumW == 0) {
            return null;
        }
        return new Pose(sumX / sumW, sumY / sumW, head);
    }

    /** A seen flag or goal with identity, distance and direction; null for anything else. */
    private static Landmarks.Landmark landmark(VisualObject object) {
        ObjectKind kind = object.kind();
        if ((kind != ObjectKind.FLAG && kind != ObjectKind.GOAL) || object.behind()
                || Double.isNaN(object.distance()) || Double.isNaN(object.direction())) {
            return null;
        }
        return LANDMARKS.get(object.name());
    }

    /**
     * The head direction that best turns the seen flags' offsets onto their known positions
     * (weighted least squares about the weighted centroids), NaN with fewer than two flags.
     */
    static double flagRotation(See see) {
        int n = 0;
        double sumW = 0;
        double px = 0;
        double py = 0;
        double rx = 0;
        double ry = 0;
        for (VisualObject object : see.objects()) {
            Landmarks.Landmark landmark = landmark(object);
            if (landmark == null) {
                continue;
            }
            double d = object.distance();
            double w = 1 / Math.max(d, 1);
            double a = Math.toRadians(object.direction());
            px += w * landmark.x();
            py += w * landmark.y();
            rx += w * d * Math.cos(a);
            ry += w * d * Math.sin(a);
            sumW += w;
            n++;
        }
        if (n < 2) {
            return Double.NaN;
        }
        px /= sumW;
        py /= sumW;
        rx /= sumW;
        ry /= sumW;
        double dot = 0;
        double cross = 0;
        for (VisualObject object : see.objects()) {
            Landmarks.Landmark landmark = landmark(object);
            if (landmark == null) {
                continue;
            }
            double d = object.distance();
            double w = 1 / Math.max(d, 1);
            double a = Math.toRadians(object.direction());
            double ox = d * Math.cos(a) - rx;
            double oy = d * Math.sin(a) - ry;
            double kx = landmark.x() - px;
            double ky = landmark.y() - py;
            dot += w * (ox * kx + oy * ky);
            cross += w * (ox * ky - oy * kx);
        }
        if (dot == 0 && cross == 0) {
            return Double.NaN;
        }
        return Math.toDegrees(Math.atan2(cross, dot));
    }

    /**
     * The head direction from the first seen line: the server reports the angle between the view
     * and the line ({@code sight - 90} or {@code sight + 90}, sight being the line's normal
     * seen from the head, within 90 degrees). Which normal (the player inside the pitch or beyond
     * the line) and which sign (a reported 0 is either) are the candidates nearest {@code hint};
     * without a hint the player is taken to be inside. NaN without a usable line.
     */
    static double lineHead(See see, double hint) {
        for (VisualObject object : see.objects()) {
            if (object.kind() != ObjectKind.LINE || object.behind() || Double.isNaN(object.direction())) {
                continue;
            }
            Landmarks.Line line = LINES.get(object.name());
            if (line == null) {
                continue;
            }
            double fromInside = line.vertical() ? (line.at() > 0 ? 0 : 180) : (line.at() > 0 ? 90 : -90);
            double d = object.direction();
            double best = Double.NaN;
            double bestGap = Double.POSITIVE_INFINITY;
            for (double sight : new double[] {d + 90, d - 90}) {
                if (Math.abs(sight) > 90) {
                    continue;
                }
                for (int beyond = 0; beyond < 2; beyond++) {
                    double head = normalize(fromInside + 180 * beyond - sight);
                    double gap = Double.isNaN(hint) ? (beyond == 0 ? 0 : 1) : Math.abs(normalize(head - hint));
                    if (gap < bestGap) {
                        bestGap = gap;
                        best = head;
                    }
                }
            }
            // no candidate within 30 degrees of the guess: the reading and the guess disagree, the guess stands
            return bestGap <= 30 || Double.isNaN(hint) ? best : Double.NaN;
        }
        return Double.NaN;
    }

    /** An angle in degrees normalised to (-180, 180]. */
    static double normalize(double degrees) {
        double a = degrees % 360;
        if (a > 180) {
            a -= 360;
        } else if (a <= -180) {
            a += 360;
        }
        return a;
    }
}
