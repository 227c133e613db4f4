package org.scenes.simulator;

import org.scenes.internal.vision.Landmarks;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.scenes.api.Side;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.See;
import org.scenes.internal.protocol.VisualObject;

class VisionTest {
    private final World world = new World(ServerParams.DEFAULT, 1);
    private final Vision vision = new Vision(world);
    private final Player self = world.add("Teal", Side.LEFT, 1);

    private See see() {
        return (See) new MessageParser().parse(vision.see(self));
    }

    private static VisualObject find(See see, String name) {
        return see.objects().stream().filter(o -> o.name().equals(name)).findFirst().orElse(null);
    }

    @Test
    void flagStraightAheadHasTheQuantisedDistance() {
        self.place(0, 0);
        self.body = 0;
        // (f p r c) at (36, 0): exp(rint(ln 36 / 0.01) * 0.01) = 35.87, to 0.1 -> 35.9
        String text = vision.see(self);
        assertTrue(text.contains("((f p r c) 35.9 0)"), text);
        assertEquals(35.9, Numbers.seenDistance(36, 0.01), 1e-9);
    }

    @Test
    void directionsAreRelativeToTheHeadAndClockwisePositive() {
        self.place(0, 0);
        self.body = 90; // facing y+, i.e. down the screen towards (f c b)
        VisualObject flag = find(see(), "f c b");
        assertEquals(0, flag.direction());
        VisualObject flag10 = find(see(), "f b r 10"); // (10, 39): to the left of the view direction
        assertEquals(-Math.rint(Math.toDegrees(Math.atan2(10, 39))), flag10.direction());
    }

    @Test
    void onlyObjectsInTheViewConeAreNamed() {
        self.place(0, 0);
        self.body = 0;
        See see = see();
        assertTrue(find(see, "g r") != null);
        assertEquals(null, find(see, "g l"));
        for (VisualObject object : see.objects()) {
            assertTrue(Math.abs(object.direction()) <= 45 || object.behind() || object.kind().name().equals("LINE"),
                    object.toString());
        }
    }

    @Test
    void ballBehindWithinVisibleDistanceIsUpperCaseWithoutDetails() {
        self.place(0, 0);
        self.body = 0;
        world.ball.place(-2, 0);
        assertTrue(vision.see(self).contains("((B) 2 180)"), vision.see(self));
        world.ball.place(-4, 0);
        assertFalse(vision.see(self).contains("(B)"));
    }

    @Test
    void movingObjectsUseTheCoarserStep() {
        self.place(0, 0);
        self.body = 0;
        world.ball.place(36, 0);
        VisualObject ball = find(see(), "b");
        // exp(rint(ln 36 / 0.1) * 0.1) = 36.6
        assertEquals(36.6, ball.distance(), 1e-9);
        assertTrue(Double.isNaN(ball.distanceChange()), "no changes beyond 20 m");
        world.ball.place(10, 0);
        world.ball.vx = -1;
        VisualObject near = find(see(), "b");
        // seen distance 10 * rint(-1 / 10 / 0.02) * 0.02
        assertEquals(-1, near.distanceChange(), 1e-9);
        assertEquals(0, near.directionChange(), 1e-9);
        world.ball.place(25, 0); // 24.5 seen: changes still sent below the halfway point 30
        assertTrue(!Double.isNaN(find(see(), "b").distanceChange()));
    }

    @Test
    void playerIdentityFadesWithDistance() {
        Player other = world.add("Amber", Side.RIGHT, 7);
        self.place(0, 0);
        self.body = 0;
        other.body = 180;
        other.place(10, 0);
        VisualObject near = find(see(), "p");
        assertEquals("Amber", near.team());
        assertEquals(7, near.uniformNumber());
        assertEquals(180, Math.abs(near.bodyFacing()));
        other.place(35, 0);
        VisualObject middle = find(see(), "p");
        assertEquals("Amber", middle.team());
        assertEquals(0, middle.uniformNumber());
        other.place(55, 0);
        VisualObject far = find(see(), "p");
        assertEquals("", far.team());
    }

    @Test
    void facingALineSquarelyReportsNinetyDegrees() {
        self.place(-49.8, 28.9);
        self.body = 0;
        VisualObject line = find(see(), "l r");
        assertEquals(90, line.direction());
        assertEquals(102.5, line.distance(), 1e-9); // 102.3 m, quantised like a landmark
    }

    @Test
    void aLineSeenAtAnAngleReportsTheAngleBetweenLineAndView() {
        self.place(0, 0);
        self.body = 30; // meets (l r) at (52.5, 30.3), 60.62 m away: exp(4.10) = 60.3 seen
        See see = see();
        VisualObject line = find(see, "l r");
        assertEquals(60, line.direction());
        assertEquals(60.3, line.distance(), 1e-9);
        self.body = -30;
        assertEquals(-60, find(see(), "l r").direction());
        assertEquals(1, see.objects().stream().filter(o -> o.kind().name().equals("LINE")).count(),
                "one line from inside the pitch");
    }

    @Test
    void fromOutsideThePitchUpToTwoLines() {
        self.place(-55, -36); // beyond the top left corner, looking into the pitch
        self.body = 45;
        long lines = see().objects().stream().filter(o -> o.kind().name().equals("LINE")).count();
        assertEquals(2, lines);
    }

    @Test
    void theConeEdgeIsExcluded() {
        self.place(0, 0);
        self.body = -44.9;
        world.ball.place(10, 0); // just inside the cone
        assertTrue(find(see(), "b") != null);
        self.body = -45; // exactly on the edge: not seen, and too far to be sensed behind
        assertEquals(null, find(see(), "b"));
    }

    @Test
    void smallNegativeChangesPrintAsMinusZeroLikeTheServer() {
        self.place(0, 0);
        self.body = 0;
        world.ball.place(10, 0);
        world.ball.vx = -0.001; // radial change -0.0001 per metre quantises to -0
        assertTrue(vision.see(self).contains("((b) 10 0 -0 0)"), vision.see(self));
        assertEquals("-0", Numbers.formatChange(-0.0, 1));
        assertEquals("0", Numbers.formatChange(0.0, 1));
        assertEquals("-0.364", Numbers.formatChange(18.2 * -0.02, 4));
    }

    @Test
    void thereAre55Landmarks() {
        assertEquals(55, Landmarks.ALL.size());
        assertEquals(2, Landmarks.ALL.stream().filter(Landmarks.Landmark::goal).count());
        assertEquals(55, Landmarks.ALL.stream().map(Landmarks.Landmark::name).distinct().count());
    }

    @Test
    void senseBodyParses() {
        String text = vision.senseBody(self);
        assertTrue(new MessageParser().parse(text) instanceof org.scenes.internal.protocol.SenseBody, text);
    }
}
