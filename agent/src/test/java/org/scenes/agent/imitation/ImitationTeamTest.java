package org.scenes.agent.imitation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Action;
import org.scenes.api.ActionSelector;
import org.scenes.api.Grid;
import org.scenes.api.Observer;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.api.Side;
import org.scenes.internal.match.Recognizer;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.See;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.scene.SceneFileHeader;
import org.scenes.internal.scene.SceneFileWriter;
import org.scenes.internal.scene.SceneSource;
import org.scenes.internal.target.BallWatch;
import org.scenes.internal.target.Destinations;
import org.scenes.internal.target.Replay;
import org.scenes.simulator.Brain;
import org.scenes.simulator.BrainFactory;

/** Roles: each imitating player plays on its counterpart's scenes and takes its kick-off moves. */
class ImitationTeamTest {
    @TempDir
    Path directory;

    private static final ActionSelector FIRST = (nearest, random) -> nearest.get(0).scene().primaryAction();

    private static List<SeenObject> ballAt(double distance) {
        See see = (See) new MessageParser().parse("(see 1 ((b) " + distance + " 0))");
        return org.scenes.internal.convert.SceneConverter.seenObjects(see, Observer.UNKNOWN, Grid.DEFAULT);
    }

    /** A recorded player's file: a kick-off move, then its answer to a ball 10 m ahead. */
    private Path recorded(int unum, boolean goalie, Action move, Action answer) throws IOException {
        Observer player = new Observer("Teal", Side.LEFT, unum);
        Path file = directory.resolve("Teal_" + unum + ".json");
        SceneFileWriter.write(file, new SceneFile(SceneFileHeader.of(Grid.DEFAULT,
                new SceneSource("Teal_" + unum + ".lsf", player, goalie)), List.of(
                new Scene(0, player, ballAt(30), List.of(move)),
                new Scene(1, player, ballAt(30), List.of(move)),
                new Scene(5, player, ballAt(10), List.of(answer)))));
        return file;
    }

    private ImitationTeam team(ImitationTeam.Knowledge knowledge) throws IOException {
        List<Path> files = List.of(recorded(1, true, Action.move(-50, 0), Action.kick(100, 0)),
                recorded(2, false, Action.move(-20, 10), Action.turn(30)));
        return ImitationTeam.load(files, List::of,
                knowledge1 -> new Recognizer(knowledge1, () -> ImitationBrainTest.BALL, 1), knowledge);
    }

    /** What the player with this number sends: at its player_type, then to a ball 10 m ahead, then to one 30 m ahead. */
    private static List<String> play(BrainFactory brains, int unum) {
        Brain brain = brains.create("Teal", new Random(1));
        List<String> sent = new ArrayList<>();
        brain.receive("(init l " + unum + " before_kick_off)", sent::add);
        brain.receive("(player_type (id 0))", sent::add);
        brain.receive("(see 50 ((b) 10 0))", sent::add);
        brain.receive("(see 51 ((b) 30 0))", sent::add);
        return sent;
    }

    @Test
    void eachPlayerPlaysOnItsCounterpartsScenesAndMovesToItsSpot() throws IOException {
        BrainFactory brains = team(ImitationTeam.Knowledge.COUNTERPART).brains(() -> FIRST, List::of,
                ImitationBrain.Guards.OFF);
        assertEquals(List.of("(move -50 0)", "(kick 100 0)", "(move -50 0)"), play(brains, 1));
        assertEquals(List.of("(move -20 10)", "(turn 30)", "(move -20 10)"), play(brains, 2));
        assertTrue(brains.goalie(1), "the recorded goalie's imitator inits as goalie");
        assertFalse(brains.goalie(2));
        List<String> stranger = play(brains, 7);
        assertTrue(stranger.get(0).startsWith("(move -"), "no counterpart: a random spot, as before");
        assertEquals("(kick 100 0)", stranger.get(1), "no counterpart: the team's scenes, nearest first");
    }

    @Test
    void targetBrainsHaveEveryRolesDestinationsAndBallWatchMadeBeforeAnyInitArrives() throws IOException {
        ImitationTeam raw = team(ImitationTeam.Knowledge.COUNTERPART);
        raw.brains(() -> FIRST, List::of, ImitationBrain.Guards.OFF, Replay.RAW);
        assertFalse(Destinations.made(raw.recognizer(1).knowledge()), "raw replay needs no destinations");
        assertFalse(BallWatch.made(raw.recognizer(1).knowledge()), "nor a ball watch");
        ImitationTeam target = team(ImitationTeam.Knowledge.COUNTERPART);
        target.brains(() -> FIRST, List::of, ImitationBrain.Guards.OFF, Replay.TARGET);
        for (int unum : List.of(1, 2)) {
            assertTrue(Destinations.made(target.recognizer(unum).knowledge()), "counterpart " + unum);
            assertTrue(BallWatch.made(target.recognizer(unum).knowledge()), "counterpart " + unum);
        }
        assertTrue(Destinations.made(target.knowledge()), "the team's, for players without a counterpart");
        assertTrue(BallWatch.made(target.knowledge()), "the team's ball watch");
    }

    @Test
    void aCounterpartThatPlacedItselfWithOneMoveEachTimeIsImitatedSoThoughEveryViewMatchesIt() throws IOException {
        Observer player = new Observer("Teal", Side.LEFT, 5);
        Path file = directory.resolve("Teal_5.json");
        SceneFileWriter.write(file, new SceneFile(SceneFileHeader.of(Grid.DEFAULT, new SceneSource("h", player)),
                List.of(new Scene(0, player, ballAt(30), List.of(Action.move(-10, 5))),
                        new Scene(1, player, ballAt(31), List.of(Action.turn(30))),
                        new Scene(80, player, ballAt(32), List.of(Action.move(-10, 5))),
                        new Scene(81, player, ballAt(31), List.of(Action.turn(30))))));
        Brain brain = ImitationTeam.load(List.of(file), List::of,
                        knowledge -> new Recognizer(knowledge, () -> ImitationBrainTest.BALL, 2),
                        ImitationTeam.Knowledge.COUNTERPART).brains(() -> FIRST, List::of, ImitationBrain.Guards.OFF)
                .create("Teal", new Random(1));
        brain.receive("(init l 5 before_kick_off)", s -> { });
        List<String> sent = new ArrayList<>();
        for (int step = 0; step < 3; step++) {
            brain.receive("(see 0 ((b) 30 0))", sent::add);
        }
        assertEquals(List.of("(move -10 5)", "(turn 30)", "(turn 30)"), sent, "placed once, then the other neighbour");
        sent.clear();
        brain.receive("(hear 90 referee goal_r_1)", s -> { });
        brain.receive("(see 90 ((b) 30 0))", sent::add);
        brain.receive("(see 90 ((b) 30 0))", sent::add);
        assertEquals(List.of("(move -10 5)", "(turn 30)"), sent, "a new stop of play: placed again, once");
        // a counterpart that repeated its move on every view until the kick-off (Krislet) is imitated so
        List<String> repeated = play(team(ImitationTeam.Knowledge.COUNTERPART).brains(() -> FIRST, List::of,
                ImitationBrain.Guards.OFF), 2);
        assertEquals(List.of("(move -20 10)", "(turn 30)", "(move -20 10)"), repeated);
    }

    @Test
    void withTheTeamsKnowledgeAMoveFromAnotherPlayersSceneBecomesTheCounterpartsOwn() throws IOException {
        BrainFactory brains = team(ImitationTeam.Knowledge.TEAM).brains(() -> FIRST, List::of,
                ImitationBrain.Guards.OFF);
        // the nearest scene to a far ball is player 1's move: player 2 goes to its own spot instead
        assertEquals(List.of("(move -20 10)", "(kick 100 0)", "(move -20 10)"), play(brains, 2));
        assertEquals(List.of("(move -50 0)", "(kick 100 0)", "(move -50 0)"), play(brains, 1));
    }

    @Test
    void theKickOffMoveIsRepeatedAfterGoalsOnlyWhenTheCounterpartMovedDuringTheGame() throws IOException {
        Observer player = new Observer("Teal", Side.LEFT, 3);
        Path still = directory.resolve("Teal_3.json");
        SceneFileWriter.write(still, new SceneFile(SceneFileHeader.of(Grid.DEFAULT, new SceneSource("l", player)),
                List.of(new Scene(5, player, ballAt(10), List.of(Action.dash(50))))));
        ImitationTeam team = ImitationTeam.load(List.of(recorded(2, false, Action.move(-20, 10), Action.turn(30)), still),
                List::of, knowledge -> new Recognizer(knowledge, () -> ImitationBrainTest.BALL, 1),
                ImitationTeam.Knowledge.COUNTERPART);
        BrainFactory brains = team.brains(() -> FIRST, List::of, ImitationBrain.Guards.OFF);
        Brain moved = brains.create("Teal", new Random(1));
        moved.receive("(init l 2 before_kick_off)", s -> { });
        Brain neverMoved = brains.create("Teal", new Random(1));
        neverMoved.receive("(init l 3 before_kick_off)", s -> { });
        assertTrue(moved.repeatsKickOffMove());
        assertFalse(neverMoved.repeatsKickOffMove(), "its teacher never moved after a goal: neither does it");
        // the real Krislet client: one placement at time 0, none after goals
        Observer krislet = new Observer("Teal", Side.LEFT, 4);
        Path once = directory.resolve("Teal_4.json");
        SceneFileWriter.write(once, new SceneFile(SceneFileHeader.of(Grid.DEFAULT, new SceneSource("k", krislet)),
                List.of(new Scene(0, krislet, ballAt(30), List.of(Action.move(-10, 0))),
                        new Scene(5, krislet, ballAt(10), List.of(Action.dash(50))))));
        Brain placedOnce = ImitationTeam.load(List.of(once), List::of,
                        knowledge -> new Recognizer(knowledge, () -> ImitationBrainTest.BALL, 1),
                        ImitationTeam.Knowledge.COUNTERPART).brains(() -> FIRST, List::of, ImitationBrain.Guards.OFF)
                .create("Teal", new Random(1));
        List<String> sent = new ArrayList<>();
        placedOnce.receive("(init l 4 before_kick_off)", sent::add);
        placedOnce.receive("(player_type (id 0))", sent::add);
        assertEquals(List.of("(move -10 0)"), sent, "it still places itself where its teacher did");
        assertFalse(placedOnce.repeatsKickOffMove(), "a placement at time 0 only is not repeated after goals");
        // nor is it matched in play: a ball 30 m ahead in play is answered by the dash, not the placement
        sent.clear();
        placedOnce.receive("(see 60 ((b) 30 0))", sent::add);
        assertEquals(List.of("(dash 50)"), sent, "the time-0 placement is not in the knowledge matched in play");
        assertTrue(team.recognizer(2).knowledge().scenes().stream()
                .anyMatch(scene -> scene.actionType() == org.scenes.api.ActionType.MOVE),
                "a counterpart that moved in play keeps its moves");
        Brain withoutRoles = new ImitationBrain("Teal", team.recognizer(3), FIRST, List::of, new Random(1));
        assertTrue(withoutRoles.repeatsKickOffMove(), "a brain without roles keeps the runtime's repeat");
    }

    /** What the player with this number answers to a ball 18 m ahead. */
    private static List<String> answerAt18(BrainFactory brains, int unum) {
        Brain brain = brains.create("Teal", new Random(1));
        List<String> sent = new ArrayList<>();
        brain.receive("(init l " + unum + " before_kick_off)", s -> { });
        brain.receive("(see 50 ((b) 18 0))", sent::add);
        return sent;
    }

    @Test
    void labelledScenesJoinTheirPlayersCounterpartAndTheTeam() throws IOException {
        ImitationTeam team = team(ImitationTeam.Knowledge.COUNTERPART);
        Observer two = new Observer("Teal", Side.LEFT, 2);
        // player 2's label: a dash at a ball 20 m ahead, nearer 18 m than any recorded scene (10 m, 30 m)
        ImitationTeam labelled = team.plus(java.util.Map.of(2, List.of(List.of(
                        new Scene(60, two, ballAt(20), List.of(Action.dash(77)))))), List::of,
                knowledge -> new Recognizer(knowledge, () -> ImitationBrainTest.BALL, 1));
        BrainFactory brains = labelled.brains(() -> FIRST, List::of, ImitationBrain.Guards.OFF);
        assertEquals(List.of("(dash 77)"), answerAt18(brains, 2));
        assertEquals(List.of("(kick 100 0)"), answerAt18(brains, 1), "player 1's own scenes did not change");
        assertEquals(team.scenes() + 1, labelled.scenes(), "the team's knowledge holds the label too");
        assertEquals(List.of("(turn 30)"), answerAt18(team.brains(() -> FIRST, List::of, ImitationBrain.Guards.OFF), 2),
                "the team it was made from is unchanged");
        assertTrue(brains.goalie(1), "roles stay");
        assertEquals("(move -20 10)", play(brains, 2).get(0), "and the counterpart's kick-off move");
    }

    @Test
    void aPlayerWhoseCounterpartNeverTookAKickOffTakesItAsTheTeamDid() throws IOException {
        List<Path> files = new ArrayList<>();
        for (int unum : new int[] {3, 4}) {
            Observer player = new Observer("Teal", Side.LEFT, unum);
            List<Scene> scenes = new ArrayList<>();
            for (int t = 0; t <= 25; t++) {
                // player 3 waits 25 cycles at its kick-off, then kicks; player 4 only turns
                Action action = unum == 3 && t == 25 ? Action.kick(40, 90) : Action.turn(10);
                scenes.add(new Scene(t, player, List.of(), List.of(action), null, 0, new org.scenes.api.World(-0.3, 0,
                        0, 0, 0, 0, 8000, 1, 0, 0, 0, 0, 0, 0, List.of(), "kick_off_l", 0, 0)));
            }
            Path file = directory.resolve("Teal_" + unum + ".json");
            SceneFileWriter.write(file, new SceneFile(SceneFileHeader.of(Grid.DEFAULT,
                    new SceneSource("Teal_" + unum + ".lsf", player)), scenes));
            files.add(file);
        }
        ImitationTeam team = ImitationTeam.load(files, List::of,
                knowledge -> new Recognizer(knowledge, () -> ImitationBrainTest.BALL, 1),
                ImitationTeam.Knowledge.COUNTERPART);
        assertEquals(Action.kick(40, 90), team.setPlayKicks(4).due("kick_off_l", Side.LEFT, 25, 0, 0).primaryAction());
        assertNull(team.setPlayKicks(4).due("kick_off_l", Side.LEFT, 24, 0, 0));
        assertEquals(Action.kick(40, 90), team.setPlayKicks(3).due("kick_off_l", Side.LEFT, 25, 0, 0).primaryAction());
        assertEquals(Action.kick(40, 90), team.setPlayKicks(9).due("kick_off_l", Side.LEFT, 30, 0, 0).primaryAction(),
                "no counterpart: the team's");
    }

    @Test
    void kickOffMovesAreTheFirstOfEachRunOfMoves() {
        Observer player = new Observer("Teal", Side.LEFT, 3);
        List<Scene> scenes = new ArrayList<>();
        for (Action action : List.of(Action.move(-1, 1), Action.move(-2, 2), Action.dash(10), Action.move(-3, 3),
                Action.turn(5), Action.move(-1, 1))) {
            scenes.add(new Scene(scenes.size(), player, List.of(), List.of(action)));
        }
        assertEquals(List.of(Action.move(-1, 1), Action.move(-3, 3), Action.move(-1, 1)),
                ImitationTeam.kickOffMoves(scenes));
    }

    /** Standing at (-0.5, 0), facing x+: the ball on the centre spot at its feet, two flags and the goal ahead. */
    private static final String AT_THE_BALL = "((f c) 0.5 0) ((f p r t) 41.7 -29) ((f p r b) 41.7 29) ((g r) 53 0) ((b) 0.5 0)";

    /**
     * What player 10 sends at its first see after the referee called {@code mode}, at the ball on
     * the centre spot: its first scene kicks in play (the nearest of every query: the metric is 0),
     * then it waited 20 cycles at a kick-off of its own and passed back.
     */
    private List<String> firstAnswerAtTheBall(String mode) throws IOException {
        Observer ten = new Observer("Teal", Side.LEFT, 10);
        List<Scene> scenes = new ArrayList<>();
        for (int t = 0; t <= 21; t++) {
            Action action = t == 0 ? Action.kick(100, 0) : t == 21 ? Action.kick(50, 180) : Action.turn(30);
            scenes.add(new Scene(t, ten, List.of(), List.of(action), null, 0, new org.scenes.api.World(-0.5, 0, 0, 0,
                    0, 0, 8000, 1, 0, 0, 0, 0, 0, 0, List.of(), t == 0 ? "play_on" : "kick_off_l", 0, 0)));
        }
        Path file = directory.resolve("Teal_10.json");
        SceneFileWriter.write(file, new SceneFile(SceneFileHeader.of(Grid.DEFAULT, new SceneSource("Teal_10.lsf", ten)),
                scenes));
        Brain brain = ImitationTeam.load(List.of(file), List::of,
                        knowledge -> new Recognizer(knowledge, () -> (query, stored) -> 0, 1),
                        ImitationTeam.Knowledge.COUNTERPART).brains(() -> FIRST, List::of, ImitationBrain.Guards.OFF)
                .create("Teal", new Random(1));
        return ImitationBrainTest.firstAnswerAfter(brain, 10, mode, AT_THE_BALL);
    }

    /**
     * Player 10 kicks in play, then waited 20 cycles at a kick-off of its own and passed back;
     * player 7 only ever kicked in play. Both stand at the ball on the centre spot at a kick-off
     * of their own; what each sends at the sees of {@code cycles}, one list per see.
     */
    private List<List<String>> atTheKickOff(int unum, int... cycles) throws IOException {
        List<Path> files = new ArrayList<>();
        for (int recorded : new int[] {7, 10}) {
            Observer player = new Observer("Teal", Side.LEFT, recorded);
            List<Scene> scenes = new ArrayList<>();
            for (int t = 0; t <= 21; t++) {
                boolean kickOff = recorded == 10 && t > 0;
                Action action = !kickOff ? Action.kick(100, 0) : t == 21 ? Action.kick(50, 180) : Action.turn(30);
                scenes.add(new Scene(t, player, List.of(), List.of(action), null, 0, new org.scenes.api.World(-0.5, 0, 0,
                        0, 0, 0, 8000, 1, 0, 0, 0, 0, 0, 0, List.of(), kickOff ? "kick_off_l" : "play_on", 0, 0)));
            }
            Path file = directory.resolve("Teal_" + recorded + ".json");
            SceneFileWriter.write(file, new SceneFile(SceneFileHeader.of(Grid.DEFAULT,
                    new SceneSource("Teal_" + recorded + ".lsf", player)), scenes));
            files.add(file);
        }
        Brain brain = ImitationTeam.load(files, List::of, knowledge -> new Recognizer(knowledge, () -> (query, stored) -> 0, 1),
                ImitationTeam.Knowledge.COUNTERPART).brains(() -> FIRST, List::of, ImitationBrain.Guards.OFF)
                .create("Teal", new Random(1));
        brain.receive("(init l " + unum + " before_kick_off)", command -> { });
        brain.receive("(hear 0 referee kick_off_l)", command -> { });
        List<List<String>> answers = new ArrayList<>();
        for (int cycle : cycles) {
            List<String> sent = new ArrayList<>();
            brain.receive("(see " + cycle + " " + AT_THE_BALL + ")", sent::add);
            answers.add(sent);
        }
        return answers;
    }

    @Test
    void aPlayerWhoseCounterpartNeverTookAKickOffLeavesItToTheTakerForTwiceTheTeamsWait() throws IOException {
        assertEquals(List.of(List.of("(kick 50 180)")), atTheKickOff(10, 1), "the taker: the recorded kick-off");
        List<List<String>> seven = atTheKickOff(7, 1, 30, 45);
        assertTrue(seven.get(0).stream().noneMatch(command -> command.startsWith("(kick")),
                "not the kick it matched: " + seven.get(0));
        assertTrue(seven.get(1).stream().noneMatch(command -> command.startsWith("(kick")),
                "still the taker's after 29 cycles: " + seven.get(1));
        assertEquals(List.of("(kick 50 180)"), seven.get(2), "after twice the team's wait of 20: as the team kicked off");
    }

    @Test
    void aKickMatchedAtTheBallOfItsOwnSetPlayIsTheRecordedOneEvenBeforeTheWait() throws IOException {
        assertEquals(List.of("(kick 50 180)"), firstAnswerAtTheBall("kick_off_l"), "the recorded kick-off, not the kick in play");
        assertEquals(List.of("(kick 100 0)"), firstAnswerAtTheBall("play_on"), "in play the matched kick");
        assertEquals(List.of("(kick 100 0)"), firstAnswerAtTheBall("kick_off_r"), "the other team's kick-off is not its own");
    }
}
