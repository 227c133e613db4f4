package org.scenes.properties;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.function.Consumer;
import net.jqwik.api.Example;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.See;
import org.scenes.internal.protocol.VisualObject;
import org.scenes.internal.vision.Fading;
import org.scenes.internal.vision.SeeWriter;
import org.scenes.internal.vision.VisionParams;

/**
 * The game-log converter takes a rebuilt see as the objects the vision model gives, not as text
 * it would write and read back: for any view, those objects are what the parser reads from the
 * text the same model writes (every number, -0 and NaN included), so scenes are the same either way.
 */
class RebuiltSeePropertiesTest {
    /** Version 18's player types: teams shown to the far length, then never (far and too far equal). */
    private static final VisionParams V18 = new VisionParams(3, 0.1, 0.01, 20, 40, 40, 40, 20, 40, 20, 40);

    @Property(tries = 400)
    void theObjectsOfASeeAreWhatTheParserReadsFromItsText(@ForAll long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        VisionParams params = random.nextBoolean() ? VisionParams.DEFAULT : V18;
        double[] self = {random.nextDouble(-58, 58), random.nextDouble(-39, 39), random.nextDouble(-1, 1),
            random.nextDouble(-1, 1), random.nextDouble(-180, 180)};
        double cone = new double[] {45, 60, 90, 120, 180, 360}[random.nextInt(6)];
        boolean high = random.nextInt(5) > 0;
        List<double[]> players = new ArrayList<>();
        for (int i = 0; i < 22; i++) {
            // some players stand where the observer stands: a distance of 0, no changes
            boolean onTop = random.nextInt(30) == 0;
            players.add(new double[] {onTop ? self[0] : random.nextDouble(-55, 55),
                onTop ? self[1] : random.nextDouble(-36, 36), random.nextDouble(-1, 1), random.nextDouble(-1, 1),
                random.nextDouble(-180, 180), random.nextDouble(-90, 90)});
        }
        double[] ball = {random.nextDouble(-54, 54), random.nextDouble(-35, 35), random.nextDouble(-3, 3),
            random.nextDouble(-3, 3)};
        assertSameSee(params, seed, writer -> {
            writer.landmarks();
            writer.ball(ball[0], ball[1], ball[2], ball[3]);
            for (int i = 0; i < players.size(); i++) {
                double[] p = players.get(i);
                writer.player(p[0], p[1], p[2], p[3], i < 11 ? "Teal" : "Amber", i % 11 + 1, i % 11 == 0, p[4],
                        p[4] + p[5]);
            }
            writer.lines();
        }, self, cone, high);
    }

    @Example
    void aStillBallRightBeforeTheObserverComesWithDistanceChangesOfMinusZeroAsTheServerWritesThem() {
        // the observer runs away from a still ball: its distance change is negative and may round to -0
        assertSameSee(VisionParams.DEFAULT, 1, writer -> {
            writer.ball(10, 0, 0, 0);
            writer.ball(10, 0.001, 0, 0);
        }, new double[] {0, 0, 1e-4, 0, 0}, 90, true);
    }

    private static void assertSameSee(VisionParams params, long seed, Consumer<SeeWriter> objects, double[] self,
                                      double cone, boolean high) {
        SeeWriter asText = new SeeWriter(params, Fading.dice(seed));
        StringBuilder text = new StringBuilder();
        asText.begin(text, 42, self[0], self[1], self[2], self[3], self[4], cone, high);
        objects.accept(asText);
        asText.end();
        SeeWriter asObjects = new SeeWriter(params, Fading.dice(seed));
        List<VisualObject> built = new ArrayList<>();
        asObjects.begin(built, self[0], self[1], self[2], self[3], self[4], cone, high);
        objects.accept(asObjects);
        asObjects.end();
        See read = (See) new MessageParser().parse(text.toString());
        assertEquals(read.objects(), built, text::toString);
    }
}
