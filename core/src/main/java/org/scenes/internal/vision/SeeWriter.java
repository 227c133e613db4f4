package org.scenes.internal.vision;

import java.util.List;
import java.util.Objects;
import org.scenes.api.ObjectKind;
import org.scenes.internal.protocol.VisualObject;

/**
 * Writes the {@code see} a player gets, as version 7-17 text, from where everything is: the
 * server's vision model as this project reproduces it (docs/conversion.md, "Scenes from game
 * logs"). Objects in the view cone get their quantised distance and direction (and, near enough,
 * their changes, a player's team, number and facing); objects behind within
 * {@code visible_distance} come in upper case without identity; lines as the server finds them.
 * The simulator and the game-log converter both see through it: the simulator's clients get the
 * text; the converter takes the objects a parser reads from that text, without the text.
 *
 * <p>Use: {@link #begin} (text or objects), then {@link #landmarks}, {@link #ball}, each {@link #player} and
 * {@link #lines} in the server's order, then {@link #end}. Not thread-safe.
 */
public final class SeeWriter {
    private final VisionParams p;
    private final Fading fading;
    /** Squared visible distance plus a metre. */
    private final double clearlyFar2;

    /** Where the see goes: its text, or (when text is null) its objects. */
    private StringBuilder text;
    private List<VisualObject> objects;
    private double selfX;
    private double selfY;
    private double selfVx;
    private double selfVy;
    private double head;
    /** The view cone of the see being written: half its angle, the cheap test's bound, whether it applies. */
    private double halfAngle;
    private double clearlyOutsideCos2;
    private boolean narrowView;
    private boolean highQuality;
    /** The head's unit vector. */
    private double headX;
    private double headY;

    public SeeWriter(VisionParams params, Fading fading) {
        this.p = Objects.requireNonNull(params, "params");
        this.fading = Objects.requireNonNull(fading, "fading");
        this.clearlyFar2 = (p.visibleDistance() + 1) * (p.visibleDistance() + 1);
    }

    /**
     * Starts the see of {@code time} into {@code out} for a player at ({@code x}, {@code y}) moving
     * at ({@code vx}, {@code vy}), its head (body + neck) towards {@code head} degrees, its view cone
     * {@code cone} degrees wide.
     */
    public void begin(StringBuilder out, int time, double x, double y, double vx, double vy, double head,
                      double cone, boolean highQuality) {
        this.text = out;
        this.objects = null;
        start(x, y, vx, vy, head, cone, highQuality);
        out.append("(see ").append(time);
    }

    /**
     * The same see as objects into {@code out}, each as a reader of {@link #begin}'s text gets it
     * (for the converter, which then need not read the text it wrote).
     */
    public void begin(List<VisualObject> out, double x, double y, double vx, double vy, double head, double cone,
                      boolean highQuality) {
        this.text = null;
        this.objects = out;
        start(x, y, vx, vy, head, cone, highQuality);
    }

    private void start(double x, double y, double vx, double vy, double head, double cone, boolean highQuality) {
        this.selfX = x;
        this.selfY = y;
        this.selfVx = vx;
        this.selfVy = vy;
        this.head = head;
        this.highQuality = highQuality;
        halfAngle = cone / 2;
        double cos = Math.cos(Math.toRadians(halfAngle + 1));
        clearlyOutsideCos2 = cos * cos;
        // The cheap test needs a cone under 178 degrees.
        narrowView = halfAngle + 1 < 90;
        headX = Math.cos(Math.toRadians(head));
        headY = Math.sin(Math.toRadians(head));
    }

    /** The flags and goals, in {@link Landmarks#ALL}'s order. */
    public void landmarks() {
        for (Landmarks.Landmark landmark : Landmarks.ALL) {
            object(landmark.name(), landmark.goal() ? "G" : "F", landmark.x(), landmark.y(), 0, 0, p.quantizeStepL(),
                    null, 0, false, 0, 0, p.flagChgFarLength(), p.flagChgTooFarLength());
        }
    }

    public void ball(double x, double y, double vx, double vy) {
        object("b", "B", x, y, vx, vy, p.quantizeStep(), null, 0, false, 0, 0, p.ballVelFarLength(),
                p.ballVelTooFarLength());
    }

    /** Another player, its body and head (body + neck) directions in degrees. */
    public void player(double x, double y, double vx, double vy, String team, int unum, boolean goalie, double body,
                       double playerHead) {
        object(null, "P", x, y, vx, vy, p.quantizeStep(), team, unum, goalie, body, playerHead, p.unumFarLength(),
                p.unumTooFarLength());
    }

    /** Ends the see. */
    public void end() {
        if (text != null) {
            text.append(')');
        }
        text = null;
        objects = null;
    }

    /**
     * One object, or nothing when it is neither in the view cone nor within
     * {@code visible_distance}; {@code team} is the seen player's, null for the rest.
     */
    private void object(String name, String behindName, double x, double y, double vx, double vy,
                        double quantizeStep, String team, int unum, boolean goalie, double body, double playerHead,
                        double changesFar, double changesTooFar) {
        double dx = x - selfX;
        double dy = y - selfY;
        if (narrowView && clearlyUnseen(dx, dy)) {
            return;
        }
        double distance = Math.hypot(dx, dy);
        double direction = VisionNumbers.normalize(Math.toDegrees(Math.atan2(dy, dx)) - head);
        boolean behind = Math.abs(direction) >= halfAngle;
        if (behind && distance > p.visibleDistance()) {
            return;
        }
        double seenDirection = Math.rint(direction);
        if (!highQuality) {
            // low quality: only the direction, players by team alone
            if (behind) {
                seen(behindName, "", 0, false, Double.NaN, seenDirection);
            } else if (team == null) {
                seen(name, "", 0, false, Double.NaN, seenDirection);
            } else {
                seen("p", fading.shown(distance, p.teamFarLength(), p.teamTooFarLength()) ? team : "", 0, false,
                        Double.NaN, seenDirection);
            }
            return;
        }
        double seenDistance = VisionNumbers.seenDistance(distance, quantizeStep);
        if (behind) {
            seen(behindName, "", 0, false, seenDistance, seenDirection);
            return;
        }
        boolean changes;
        String seenName = name;
        String seenTeam = "";
        int seenUnum = 0;
        if (team == null) {
            changes = fading.shown(seenDistance, changesFar, changesTooFar);
        } else if (fading.shown(seenDistance, p.teamFarLength(), p.teamTooFarLength())) {
            seenName = "p";
            seenTeam = team;
            // a player's changes and facing come with its number
            changes = fading.shown(seenDistance, changesFar, changesTooFar);
            seenUnum = changes ? unum : 0;
        } else {
            seenName = "p";
            changes = false;
        }
        boolean seenGoalie = seenUnum > 0 && goalie;
        if (!changes || distance <= 0) {
            seen(seenName, seenTeam, seenUnum, seenGoalie, seenDistance, seenDirection);
            return;
        }
        // Relative velocity split along and across the line of sight; the radial part is
        // quantised relative to the distance and scaled by the seen distance, as the server does.
        double rvx = vx - selfVx;
        double rvy = vy - selfVy;
        double ex = dx / distance;
        double ey = dy / distance;
        double distanceChange = seenDistance * VisionNumbers.quantize((rvx * ex + rvy * ey) / distance, 0.02);
        double directionChange = Math.toDegrees((rvy * ex - rvx * ey) / distance);
        // An exactly zero direction change stays 0; a tiny negative one quantises to -0.
        directionChange = directionChange == 0 ? 0 : VisionNumbers.quantize(directionChange, 0.1);
        double seenBody = team == null ? Double.NaN : Math.rint(VisionNumbers.normalize(body - head));
        double seenHead = team == null ? Double.NaN : Math.rint(VisionNumbers.normalize(playerHead - head));
        seen(seenName, seenTeam, seenUnum, seenGoalie, seenDistance, seenDirection, distanceChange, directionChange,
                seenBody, seenHead);
    }

    /** An object seen without changes: its distance (NaN: none, low quality) and direction. */
    private void seen(String name, String team, int unum, boolean goalie, double distance, double direction) {
        seen(name, team, unum, goalie, distance, direction, Double.NaN, Double.NaN, Double.NaN, Double.NaN);
    }

    /**
     * One object into the text or the objects: NaN for a number not sent (the changes of an object
     * too far, a facing other than a player's).
     */
    private void seen(String name, String team, int unum, boolean goalie, double distance, double direction,
                      double distanceChange, double directionChange, double body, double playerHead) {
        if (objects != null) {
            objects.add(new VisualObject(kindOf(name), name, team, unum, goalie, read(distance, 1),
                    VisionNumbers.asRead(direction, 0), readChange(distanceChange, 4), readChange(directionChange, 1),
                    read(body, 0), read(playerHead, 0), Double.NaN, ' '));
            return;
        }
        name(name, team, unum, goalie);
        if (!Double.isNaN(distance)) {
            VisionNumbers.append(text, distance, 1).append(' ');
        }
        VisionNumbers.append(text, direction, 0);
        if (!Double.isNaN(distanceChange)) {
            VisionNumbers.appendChange(text.append(' '), distanceChange, 4);
            VisionNumbers.appendChange(text.append(' '), directionChange, 1);
        }
        if (!Double.isNaN(body)) {
            VisionNumbers.append(text.append(' '), body, 0);
            VisionNumbers.append(text.append(' '), playerHead, 0);
        }
        text.append(')');
    }

    /** What a reader gets from the number's text; NaN for a number not sent. */
    private static double read(double value, int decimals) {
        return Double.isNaN(value) ? Double.NaN : VisionNumbers.asRead(value, decimals);
    }

    private static double readChange(double value, int decimals) {
        return Double.isNaN(value) ? Double.NaN : VisionNumbers.asReadChange(value, decimals);
    }

    /** {@code " ((NAME) "}, a player's as {@code p "TEAM" UNUM goalie} as far as it is readable. */
    private void name(String name, String team, int unum, boolean goalie) {
        text.append(" ((").append(name);
        if (!team.isEmpty()) {
            text.append(" \"").append(team).append('"');
            if (unum > 0) {
                text.append(' ').append(unum);
                if (goalie) {
                    text.append(" goalie");
                }
            }
        }
        text.append(") ");
    }

    private static ObjectKind kindOf(String name) {
        return switch (Character.toLowerCase(name.charAt(0))) {
            case 'b' -> ObjectKind.BALL;
            case 'g' -> ObjectKind.GOAL;
            case 'f' -> ObjectKind.FLAG;
            case 'p' -> ObjectKind.PLAYER;
            default -> ObjectKind.LINE;
        };
    }

    /**
     * Whether an object is beyond visible_distance and more than a degree outside the view cone:
     * a cheap test without trigonometry that skips most objects of a see (three in four lie
     * outside a 90 degree cone). The margins leave every borderline case to the exact test.
     */
    private boolean clearlyUnseen(double dx, double dy) {
        double squared = dx * dx + dy * dy;
        if (squared <= clearlyFar2) {
            return false;
        }
        double along = dx * headX + dy * headY;
        return along <= 0 || along * along < clearlyOutsideCos2 * squared;
    }

    /**
     * Lines as the server sends them: a line is seen when the view direction points towards it
     * (less than 90 degrees from its outward normal) and meets it within its length; from inside
     * the pitch only the first such line in the order left, right, top, bottom, from outside up
     * to two. Distance along the view direction (landmark quantisation); direction the angle
     * between the view direction and the line, 90 when facing it squarely.
     */
    public void lines() {
        boolean inside = Math.abs(selfX) < Landmarks.PITCH_HALF_LENGTH && Math.abs(selfY) < Landmarks.PITCH_HALF_WIDTH;
        int wanted = inside ? 1 : 2;
        for (Landmarks.Line line : Landmarks.LINES) {
            if (wanted == 0) {
                return;
            }
            double position = line.vertical() ? selfX : selfY;
            double toLine = line.at() - position;
            // The normal points from the player's side of the line across it.
            double normal = line.vertical() ? (toLine >= 0 ? 0 : 180) : (toLine >= 0 ? 90 : -90);
            double sight = VisionNumbers.normalize(normal - head);
            if (Math.abs(sight) >= 90) {
                continue;
            }
            double radians = Math.toRadians(head);
            double along = line.vertical() ? Math.cos(radians) : Math.sin(radians);
            double distance = toLine / along;
            double across = line.vertical() ? selfY + distance * Math.sin(radians) : selfX + distance * Math.cos(radians);
            double halfLength = line.vertical() ? Landmarks.PITCH_HALF_WIDTH : Landmarks.PITCH_HALF_LENGTH;
            if (Math.abs(across) > halfLength) {
                continue;
            }
            double direction = sight > 0 ? sight - 90 : sight + 90;
            seen(line.name(), "", 0, false, VisionNumbers.seenDistance(Math.abs(distance), p.quantizeStepL()),
                    Math.rint(direction));
            wanted--;
        }
    }
}
