package org.scenes.internal.convert;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.PlayerState;
import org.scenes.internal.protocol.MessageParser;

/** The rebuilt sense_body, given as objects, is what the parser reads from the server's text of it. */
class PerceptWriterTest {
    private final MessageParser parser = new MessageParser();

    private static PlayerState state(double vx, double vy, double body, double neck, double stamina, double effort,
                                     char quality, double width) {
        return new PlayerState(Side.LEFT, 7, 0, PlayerState.STANDING, -12, 13.5, vx, vy, body, neck, quality, width,
                stamina, effort, 1, 130600, new PlayerState.Counts(3, 40, 12, 0, 1, 20, 2, 5, 0, 0, 0));
    }

    @Test
    void aMovingPlayersSenseBodyIsTheServersTextAsRead() {
        // speed 0.3606 -> 0.36; its direction 33.69 degrees, 3.69 off the head (body 10 + neck 20) -> 4
        PlayerState self = state(0.3, 0.2, 10, 20, 7696.4, 0.9084914, 'h', 90);
        assertEquals(parser.parse("(sense_body 17 (view_mode high normal) (stamina 7696 0.908491 130600)"
                        + " (speed 0.36 4) (head_angle 20) (kick 3) (dash 40) (turn 12) (say 5) (turn_neck 20)"
                        + " (catch 0) (move 1) (change_view 2))"),
                PerceptWriter.senseBodyOf(self, 17));
    }

    @Test
    void aStillPlayerWithItsNeckJustLeftOfStraightReadsAsTheTextsZeros() {
        // a neck of -0.3 rounds to -0, which the server writes as 0; a still player's direction is 0
        PlayerState self = state(0, 0, -170, -0.3, 8000, 1, 'l', 180);
        assertEquals(parser.parse("(sense_body 0 (view_mode low wide) (stamina 8000 1 130600) (speed 0 0)"
                        + " (head_angle 0) (kick 3) (dash 40) (turn 12) (say 5) (turn_neck 20) (catch 0) (move 1)"
                        + " (change_view 2))"),
                PerceptWriter.senseBodyOf(self, 0));
    }
}
