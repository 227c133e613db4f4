package org.scenes.agent.imitation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.internal.files.Inputs;
import org.scenes.internal.protocol.ViewWidth;
import org.scenes.simulator.Brain;
import org.scenes.simulator.BrainFactory;
import org.scenes.simulator.GameResult;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.Simulator;
import org.scenes.simulator.teacher.Teachers;

/** A player asks for its view right after its placement, synchronous vision first on a synchronous server. */
class ViewingTest {
    @TempDir
    Path directory;

    /** A brain that places itself at its first player_type, as the imitator does. */
    private static final BrainFactory PLACING = (team, random) -> new Brain() {
        private boolean placed;

        @Override
        public void receive(String message, java.util.function.Consumer<String> send) {
            if (!placed && message.startsWith("(player_type")) {
                placed = true;
                send.accept("(move -10 0)");
            }
        }
    };

    private static List<String> sentDuringWelcome(ViewWidth width, int synchMode) {
        Brain brain = Viewing.with(PLACING, width).create("Teal", new Random(1));
        List<String> sent = new ArrayList<>();
        brain.receive("(init l 3 before_kick_off)", sent::add);
        brain.receive("(server_param (player_size 0.3)(synch_mode " + synchMode + "))", sent::add);
        brain.receive("(player_param (player_types 18))", sent::add);
        brain.receive("(player_type (id 0)(player_speed_max 1.05))", sent::add);
        brain.receive("(player_type (id 1)(player_speed_max 1.05))", sent::add);
        brain.receive("(sense_body 0 (view_mode high normal))", sent::add);
        return sent;
    }

    @Test
    void onASynchronousServerItAsksForSynchronousVisionThenTheWidthOnceAfterItsMove() {
        assertEquals(List.of("(move -10 0)", "(synch_see)", "(change_view narrow)"),
                sentDuringWelcome(ViewWidth.NARROW, 1));
    }

    @Test
    void inRealTimeItOnlyChangesTheWidth() {
        assertEquals(List.of("(move -10 0)", "(change_view wide)"), sentDuringWelcome(ViewWidth.WIDE, 0));
    }

    @Test
    void withoutAWidthTheBrainsAreLeftAsTheyAre() {
        assertSame(PLACING, Viewing.with(PLACING, null));
    }

    @Test
    void aNarrowViewSeesMoreOftenInTheSimulator() throws IOException {
        long normal = sees(Teachers.byName("krislet"), "normal");
        long narrow = sees(Viewing.with(Teachers.byName("krislet"), ViewWidth.NARROW), "narrow");
        // real time, version 9: a see every 150 ms on a normal view, every 75 ms on a narrow one
        assertTrue(narrow > 1.8 * normal, narrow + " sees on a narrow view, " + normal + " on a normal one");
    }

    private long sees(BrainFactory brains, String name) throws IOException {
        GameResult game = new Simulator(new GameSetup(new GameSetup.Team("Teal", 1, brains),
                new GameSetup.Team("Amber", 1, Teachers.byName("krislet")), 300, 3, directory.resolve(name))).run(t -> { });
        Path log = game.logs().get(0);
        assertTrue(log.getFileName().toString().startsWith("Teal_1"), log.toString());
        try (InputStream in = Inputs.open(log)) {
            String text = new String(in.readAllBytes(), StandardCharsets.UTF_8);
            assertEquals(name.equals("narrow") ? 1 : 0, text.lines().filter(l -> l.contains("(change_view narrow)")).count());
            return text.lines().filter(line -> line.contains("(see ")).count();
        }
    }
}
