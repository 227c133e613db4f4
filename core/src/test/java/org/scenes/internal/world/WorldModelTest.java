package org.scenes.internal.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Grid;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.World;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.vision.Fading;
import org.scenes.internal.vision.SeeWriter;
import org.scenes.internal.vision.VisionParams;

/** The world model from percepts written by the server's vision model at known positions. */
class WorldModelTest {
    private final MessageParser parser = new MessageParser();
    private final SeeWriter writer = new SeeWriter(VisionParams.DEFAULT, Fading.HALFWAY);

    @TempDir
    Path dir;

    /** What a player at (x, y), head towards {@code head}, sees, with the ball and one opponent. */
    private String see(int time, double x, double y, double head, double ballX, double ballY) {
        return see(time, x, y, head, ballX, ballY, 0);
    }

    private String see(int time, double x, double y, double head, double ballX, double ballY, double ballVx) {
        StringBuilder text = new StringBuilder();
        writer.begin(text, time, x, y, 0, 0, head, 90, true);
        writer.landmarks();
        writer.ball(ballX, ballY, ballVx, 0);
        writer.player(x + 5, y + 1, 0, 0, "Them", 7, false, 0, 0);
        writer.lines();
        writer.end();
        return text.toString();
    }

    /** The same see with the ball left out, as the server sends it when the ball is not in view. */
    private String seeWithoutBall(int time, double x, double y, double head) {
        StringBuilder text = new StringBuilder();
        writer.begin(text, time, x, y, 0, 0, head, 90, true);
        writer.landmarks();
        writer.lines();
        writer.end();
        return text.toString();
    }

    private WorldModel model(char side) {
        return model(side, "before_kick_off");
    }

    private WorldModel model(char side, String playMode) {
        WorldModel model = new WorldModel("Us");
        model.accept(parser.parse("(init " + side + " 3 " + playMode + ")"));
        return model;
    }

    @Test
    void aPlayerIsPlacedWithinAFewDecimetresAndDegreesAnywhereOnThePitch() {
        Random random = new Random(5);
        List<Double> errors = new ArrayList<>();
        for (int i = 0; i < 500; i++) {
            double x = -50 + 100 * random.nextDouble();
            double y = -32 + 64 * random.nextDouble();
            double head = -180 + 360 * random.nextDouble();
            WorldModel model = model('l');
            model.accept(parser.parse("(sense_body 1 (stamina 8000 1) (speed 0 0) (head_angle 20))"));
            model.accept(parser.parse(see(1, x, y, head, x + 3, y)));
            World world = model.snapshot(1);
            assertTrue(world.located(), "placed at " + x + ", " + y + ", head " + head);
            errors.add(Math.hypot(world.x() - x, world.y() - y));
            assertEquals(0, Localisation.normalize(world.body() - (head - 20)), 1.5, "body at " + x + ", " + y);
            assertEquals(20, world.neck());
            assertEquals(8000, world.stamina());
        }
        errors.sort(null);
        assertTrue(errors.get(250) < 0.25, "median " + errors.get(250));
        assertTrue(errors.get(450) < 0.6, "p90 " + errors.get(450));
    }

    @Test
    void theRightTeamSeesTheFieldTurnedSoItAttacksTowardsPlusX() {
        WorldModel left = model('l');
        WorldModel right = model('r');
        String text = see(1, -20, 10, 30, -15, 12);
        left.accept(parser.parse(text));
        right.accept(parser.parse(text));
        World l = left.snapshot(1);
        World r = right.snapshot(1);
        assertEquals(-20, l.x(), 0.3);
        assertEquals(10, l.y(), 0.3);
        assertEquals(20, r.x(), 0.3);
        assertEquals(-10, r.y(), 0.3);
        assertEquals(30, l.body(), 1);
        assertEquals(-150, r.body(), 1);
        assertEquals(-15, l.ballX(), 0.5);
        assertEquals(15, r.ballX(), 0.5);
        assertEquals(-12, r.ballY(), 0.5);
        World.Player opponent = l.players().stream().filter(p -> p.unum() == 7).findFirst().orElseThrow();
        assertEquals(Relation.OPPONENT, opponent.relation());
        assertEquals(-15, opponent.x(), 0.5);
    }

    @Test
    void betweenSeesTheBallRollsOnAndThePlayerMovesBySenseBodysVelocity() {
        WorldModel model = model('l');
        model.accept(parser.parse("(sense_body 1 (speed 0 0) (head_angle 0))"));
        model.accept(parser.parse(see(1, 0, 0, 0, 5, 0)));
        // the ball seen again a cycle later, one metre on, its distance growing by a metre per cycle
        model.accept(parser.parse("(sense_body 2 (speed 0 0) (head_angle 0))"));
        model.accept(parser.parse(see(2, 0, 0, 0, 6, 0, 1)));
        World seen = model.snapshot(2);
        assertEquals(1, seen.ballVx(), 0.5);
        model.accept(parser.parse("(sense_body 3 (speed 0.4 0) (head_angle 0))"));
        World carried = model.snapshot(3);
        assertEquals(1, carried.ballAge());
        assertTrue(carried.ballX() > seen.ballX() + 0.5, carried.ballX() + " after " + seen.ballX());
        // 0.4 m/cycle after decay 0.4: moved a metre
        assertEquals(seen.x() + 1, carried.x(), 0.01);
        assertEquals(1, carried.age());
    }

    @Test
    void aBallNotSeenWhereEverySeeWouldShowItIsForgotten() {
        WorldModel model = model('l', "play_on");
        model.accept(parser.parse("(sense_body 1 (speed 0 0) (head_angle 0))"));
        model.accept(parser.parse(see(1, 0, 0, 0, 1, 0)));
        assertTrue(model.snapshot(1).ballKnown());
        // facing away from the ball it holds a metre ahead: a ball within the visible distance is in every see
        model.accept(parser.parse("(sense_body 2 (speed 0 0) (head_angle 0))"));
        model.accept(parser.parse(seeWithoutBall(2, 0, 0, 180)));
        World lost = model.snapshot(2);
        assertFalse(lost.ballKnown());
        assertEquals(-1, lost.ballAge());
        // seen again far ahead; then a view straight at where it was, without it
        model.accept(parser.parse(see(3, 0, 0, 0, 20, 0)));
        assertEquals(20, model.snapshot(3).ballX(), 1);
        model.accept(parser.parse(seeWithoutBall(4, 0, 0, 5)));
        assertFalse(model.snapshot(4).ballKnown());
    }

    @Test
    void aBallOutOfViewAndFartherThanTheVisibleDistanceIsKept() {
        WorldModel model = model('l', "play_on");
        model.accept(parser.parse("(sense_body 1 (speed 0 0) (head_angle 0))"));
        model.accept(parser.parse(see(1, 0, 0, 0, 10, 0)));
        model.accept(parser.parse("(sense_body 2 (speed 0 0) (head_angle 0))"));
        model.accept(parser.parse(seeWithoutBall(2, 0, 0, 90)));
        World kept = model.snapshot(2);
        assertTrue(kept.ballKnown());
        assertEquals(1, kept.ballAge());
        assertEquals(10, kept.ballX(), 1);
    }

    @Test
    void aKickOffPutsTheBallOnTheCentreSpotThoughThePlayerFacesAway() {
        WorldModel model = model('r', "play_on");
        model.accept(parser.parse("(sense_body 1 (speed 0 0) (head_angle 0))"));
        model.accept(parser.parse(see(1, 40, 5, 0, 52, 3)));
        model.accept(parser.parse("(hear 2 referee goal_r_1)"));
        model.accept(parser.parse("(hear 50 referee kick_off_l)"));
        World placed = model.snapshot(52);
        assertEquals(0, placed.ballX());
        assertEquals(0, placed.ballY());
        assertEquals(0, placed.ballVx());
        assertEquals(2, placed.ballAge());
    }

    @Test
    void theRefereeGivesPlayModeAndScoreInTheOwnTeamsTerms() {
        WorldModel model = model('r');
        assertEquals("before_kick_off", model.snapshot(0).playMode());
        model.accept(parser.parse("(hear 100 referee goal_l_1)"));
        model.accept(parser.parse("(hear 101 referee yellow_card_r_4)"));
        World afterGoal = model.snapshot(101);
        assertEquals("goal_l", afterGoal.playMode());
        assertEquals(0, afterGoal.ownScore());
        assertEquals(1, afterGoal.opponentScore());
        model.accept(parser.parse("(hear 200 referee goal_r_2)"));
        model.accept(parser.parse("(hear 201 referee kick_off_l)"));
        World later = model.snapshot(201);
        assertEquals("kick_off_l", later.playMode());
        assertEquals(2, later.ownScore());
    }

    @Test
    void theConverterGivesScenesAWorldOnlyWhenAsked() throws IOException {
        Path log = dir.resolve("p.lsf");
        Files.write(log, List.of("(init Us (version 9))", "(init l 3 before_kick_off)",
                "(sense_body 1 (stamina 7000 0.9) (speed 0 0) (head_angle -10))", see(1, -10, 5, 45, 0, 0),
                "(dash 50)", see(2, -10, 5, 45, 0, 0), "(turn 30)"), StandardCharsets.UTF_8);
        List<Scene> with = new ArrayList<>();
        List<Scene> without = new ArrayList<>();
        SceneConverter.with(Grid.DEFAULT).strict(true).world(true).build().convert(log, with::add);
        SceneConverter.with(Grid.DEFAULT).strict(true).build().convert(log, without::add);
        assertEquals(2, with.size());
        assertEquals(2, without.size());
        assertNull(without.get(0).world());
        World world = with.get(0).world();
        assertNotNull(world);
        assertEquals(-10, world.x(), 0.3);
        assertEquals(5, world.y(), 0.3);
        assertEquals(55, world.body(), 1);
        assertEquals(7000, world.stamina());
        assertEquals(0.9, world.effort());
        assertEquals("before_kick_off", world.playMode());
        assertFalse(world.players().isEmpty());
        // the objects are the same either way
        assertEquals(without.get(0).objects(), with.get(0).objects());
    }
}
