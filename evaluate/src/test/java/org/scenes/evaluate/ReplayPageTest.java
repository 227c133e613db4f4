package org.scenes.evaluate;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.PlayerState;

/** What the replay page is given to draw: the teams' colours, the legend and the ball's owner. */
class ReplayPageTest {
    @Test
    void teamsNamedAfterAColourAreDrawnInItAndTheLegendSaysWhich() {
        assertArrayEquals(new String[] {"#008080", "#ffbf00"}, ReplayPage.colours("Teal", "Amber"));
        assertArrayEquals(new String[] {"#ffbf00", "#008080"}, ReplayPage.colours("Amber_imitator", "Teal"));
        // names that are no colour: two different colours all the same
        String[] others = ReplayPage.colours("HELIOS_A", "Imitator");
        assertNotEquals(others[0], others[1]);
        String[] alike = ReplayPage.colours("Teal", "Teal_2");
        assertNotEquals(alike[0], alike[1]);
        String section = ReplayPage.section("r", List.of(frame(0, 0, List.of(player(Side.LEFT, 1, -10, 0)))));
        assertTrue(section.contains("background:#008080\"></span>Teal (left)"), section);
        assertTrue(section.contains("background:#ffbf00\"></span>Amber (right)"), section);
    }

    @Test
    void theBallsOwnerIsTheNearestPlayerWithinKickingReachFrameByFrame() throws Exception {
        List<GameFrame> frames = new ArrayList<>();
        // frame 0: the ball far from both; 1: near Teal 1 only; 2: near both, Amber 2 nearer; 3: loose again
        frames.add(frame(0, 0, List.of(player(Side.LEFT, 1, -10, 0), player(Side.RIGHT, 2, 10, 0))));
        frames.add(frame(-9.2, 0, List.of(player(Side.LEFT, 1, -10, 0), player(Side.RIGHT, 2, 10, 0))));
        frames.add(frame(0, 0, List.of(player(Side.LEFT, 1, -0.9, 0), player(Side.RIGHT, 2, 0.5, 0))));
        frames.add(frame(5, 5, List.of(player(Side.LEFT, 1, -0.9, 0), player(Side.RIGHT, 2, 0.5, 0))));
        JsonNode data = new ObjectMapper().readTree(ReplayPage.data(frames));
        assertEquals("[\"#008080\",\"#ffbf00\"]", data.get("colours").toString());
        // the owner track: 1 + the player's index (Teal 1 is 0, Amber 2 is 1), 0 for none
        assertEquals(List.of(0L, 1L, 2L, 0L), decode(data.get("owner").asText()));
    }

    private static List<Long> decode(String track) {
        List<Long> values = new ArrayList<>();
        long value = 0;
        for (int i = 0; i < track.length(); i++) {
            char c = track.charAt(i);
            if (c == '~') {
                int end = track.indexOf(';', i);
                value += Long.parseLong(track.substring(i + 1, end));
                i = end;
            } else {
                value += ReplayPage.STEPS.indexOf(c) - ReplayPage.STEP_RANGE;
            }
            values.add(value);
        }
        return values;
    }

    private static GameFrame frame(double ballX, double ballY, List<PlayerState> players) {
        return new GameFrame(0, "play_on", "Teal", "Amber", 0, 0, new GameFrame.BallState(ballX, ballY, 0, 0), players);
    }

    private static PlayerState player(Side side, int unum, double x, double y) {
        return new PlayerState(side, unum, 0, PlayerState.STANDING, x, y, 0, 0, 0, 0, 'h', 90, 8000, 1, 1, 130600,
                new PlayerState.Counts(0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0));
    }
}
