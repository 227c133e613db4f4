package org.scenes.evaluate;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.scenes.api.Side;
import org.scenes.simulator.Brain;
import org.scenes.simulator.BrainFactory;

/** A live team's players are numbered by the order their brains were made, whatever order their answers are handled in. */
class SeededPlayersTest {
    @Test
    void answersHandledOutOfOrderAreNotTakenForAnEarlierTrysPlayers() {
        List<String> notices = new ArrayList<>();
        AtomicInteger connected = new AtomicInteger();
        BrainFactory quiet = (team, random) -> (message, send) -> { };
        BrainFactory players = LiveArena.seeded(quiet, 1, Side.LEFT, new LiveArena.Scoreboard(), connected,
                new AtomicReference<>(), notices::add);
        Brain first = players.create("Teal", null);
        Brain second = players.create("Teal", null);
        // each player's thread handles its answer: the second may come first
        second.receive("(init l 2 before_kick_off)", command -> { });
        first.receive("(init l 1 before_kick_off)", command -> { });
        assertEquals(List.of(), notices);
        assertEquals(2, connected.get());
        Brain third = players.create("Teal", null);
        third.receive("(init l 5 before_kick_off)", command -> { });
        assertEquals(List.of("Teal player 3 was given uniform number 5: the server holds a player of an earlier try"
                + " (answered too late?); the game is played, but not with the numbers and seeds of the game in process"),
                notices);
    }
}
