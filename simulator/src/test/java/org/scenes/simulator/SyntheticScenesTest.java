package org.scenes.simulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.ActionType;
import org.scenes.api.Cell;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.testing.RequiresSharedData;
import org.scenes.testing.SharedData;

class SyntheticScenesTest {
    private static final int COUNT = 20_000;

    private static List<Scene> generate(long seed, int count, Grid grid) {
        List<Scene> scenes = new ArrayList<>();
        SyntheticScenes.generate(seed, count, grid, scenes::add);
        return scenes;
    }

    @Test
    void sameSeedSameScenesAndShorterRunsArePrefixes() {
        List<Scene> first = generate(42, 2000, Grid.DEFAULT);
        assertEquals(2000, first.size());
        assertEquals(first, generate(42, 2000, Grid.DEFAULT));
        assertEquals(first.subList(0, 500), generate(42, 500, Grid.DEFAULT));
        assertNotEquals(first, generate(43, 2000, Grid.DEFAULT));
    }

    @Test
    void runsFollowOneObserverWhoseCommandsTakeEffect() {
        List<Scene> runs = new ArrayList<>();
        SyntheticScenes.generate(7, 4000, 4, Grid.DEFAULT, runs::add);
        List<Scene> single = new ArrayList<>();
        SyntheticScenes.generate(7, 300, 1, Grid.DEFAULT, single::add);
        assertEquals(generate(7, 300, Grid.DEFAULT), single, "a run of 1 is the plain generator");
        assertEquals(runs, collect(7, 4000, 4), "the same seed, the same runs");
        int turnsFollowed = 0;
        int againstTheMoment = 0;
        for (int i = 0; i + 1 < runs.size(); i++) {
            Scene now = runs.get(i);
            Scene next = runs.get(i + 1);
            if ((i + 1) % 4 == 0) {
                continue; // a new run starts
            }
            assertEquals(now.observer(), next.observer(), "scene " + i);
            assertEquals(now.cycle() % 6000 + 1, next.cycle(), "scene " + i);
            SeenObject ball = ball(now);
            SeenObject after = ball(next);
            double moment = now.actionType() == ActionType.TURN ? now.primaryAction().first() : 0;
            if (Math.abs(moment) >= 10 && ball != null && after != null && ball.distance() > 10) {
                // a far ball moves little in a cycle, so the turn moves it, against the moment, by at
                // most the moment and its 10 % noise (less for a moving player: inertia)
                double moved = after.direction() - ball.direction();
                assertTrue(Math.abs(moved) <= 1.1 * Math.abs(moment) + 8, "scene " + i + ": turned " + moment
                        + ", the ball moved " + moved);
                turnsFollowed++;
                if (moved * Math.signum(moment) < 0) {
                    againstTheMoment++;
                }
            }
        }
        assertTrue(turnsFollowed > 50, "turns checked: " + turnsFollowed);
        // a fast player turns less (inertia) and the ball and player move too: nearly always, not always
        assertTrue(againstTheMoment >= 0.9 * turnsFollowed, againstTheMoment + " of " + turnsFollowed);
        assertThrows(IllegalArgumentException.class, () -> SyntheticScenes.generate(1, 10, 0, Grid.DEFAULT, s -> { }));
    }

    private static List<Scene> collect(long seed, int count, int run) {
        List<Scene> scenes = new ArrayList<>();
        SyntheticScenes.generate(seed, count, run, Grid.DEFAULT, scenes::add);
        return scenes;
    }

    private static SeenObject ball(Scene scene) {
        return scene.objects().stream().filter(o -> o.kind() == ObjectKind.BALL && o.name().equals("b")).findFirst()
                .orElse(null);
    }

    @Test
    void everyCellIsTheGridsCellOfTheObject() {
        Grid grid = new Grid(7, -60, 60, new double[] {2, 8, 20});
        for (Scene scene : generate(5, 3000, grid)) {
            for (SeenObject object : scene.objects()) {
                Cell cell = object.cell();
                assertTrue(cell.column() >= 0 && cell.column() < grid.columns(), object.toString());
                assertTrue(cell.row() >= 0 && cell.row() < grid.rows(), object.toString());
                assertEquals(grid.cell(object.distance(), object.direction()), cell, object.toString());
            }
        }
    }

    /**
     * Compared with the recorded Krislet game 1 (5 v 5): landmarks, lines and the ball within a
     * fifth of the recorded mean per scene, and more players, since synthetic games are 11 v 11.
     */
    @Test
    @RequiresSharedData
    void objectCountsAreNearRecordedKrisletScenes() throws IOException {
        double[] recorded = meanCounts(recordedGame1());
        double[] synthetic = meanCounts(generate(1, COUNT, Grid.DEFAULT));
        assertEquals(recorded[0], synthetic[0], recorded[0] * 0.2, "non-player objects per scene");
        assertTrue(synthetic[1] > recorded[1] && synthetic[1] < 21, "players per scene " + synthetic[1]
                + ", recorded " + recorded[1]);
    }

    /** Mean objects per scene without players, and mean players per scene. */
    private static double[] meanCounts(List<Scene> scenes) {
        long players = 0;
        long others = 0;
        for (Scene scene : scenes) {
            for (SeenObject object : scene.objects()) {
                if (object.kind() == ObjectKind.PLAYER) {
                    players++;
                } else {
                    others++;
                }
            }
        }
        return new double[] {(double) others / scenes.size(), (double) players / scenes.size()};
    }

    private static List<Scene> recordedGame1() throws IOException {
        Path game = SharedData.resolve("krislet/classic-game1");
        List<Scene> scenes = new ArrayList<>();
        SceneConverter converter = SceneConverter.with(Grid.DEFAULT).strict(true).build();
        for (String player : new String[] {"Carleton_1", "University_1"}) {
            converter.convert(game.resolve(player + ".lsf.gz"), scenes::add);
        }
        return scenes;
    }

    /** Every scene has the one action Krislet's rules give for its objects; all three kinds occur. */
    @Test
    void actionsFollowKrisletsRules() {
        Map<ActionType, Integer> counts = new EnumMap<>(ActionType.class);
        boolean teammates = false;
        boolean opponents = false;
        for (Scene scene : generate(7, COUNT, Grid.DEFAULT)) {
            assertEquals(1, scene.actions().size(), scene.toString());
            Action action = scene.primaryAction();
            assertEquals(expected(scene), action, scene.toString());
            counts.merge(action.type(), 1, Integer::sum);
            for (SeenObject object : scene.objects()) {
                teammates |= object.relation() == Relation.TEAMMATE;
                opponents |= object.relation() == Relation.OPPONENT && object.kind() == ObjectKind.PLAYER;
            }
        }
        // Recorded Krislet games: 66 to 75 % dashes, 25 to 34 % turns, about 0.2 % kicks.
        assertEquals(0.72, counts.get(ActionType.DASH) / (double) COUNT, 0.05, counts.toString());
        assertEquals(0.28, counts.get(ActionType.TURN) / (double) COUNT, 0.05, counts.toString());
        assertTrue(counts.getOrDefault(ActionType.KICK, 0) > 0, counts.toString());
        assertTrue(teammates && opponents);
    }

    private static Action expected(Scene scene) {
        SeenObject ball = find(scene, "b");
        if (ball == null) {
            ball = find(scene, "B"); // a ball seen behind counts
        }
        if (ball == null) {
            return Action.turn(40);
        }
        if (ball.distance() > 1) {
            return ball.direction() != 0 ? Action.turn(ball.direction()) : Action.dash(Math.rint(ball.distance() * 100) / 10);
        }
        SeenObject goal = find(scene, scene.observer().side() == org.scenes.api.Side.LEFT ? "g r" : "g l");
        return goal == null ? Action.turn(40) : Action.kick(100, goal.direction());
    }

    private static SeenObject find(Scene scene, String name) {
        return scene.objects().stream().filter(o -> o.name().equals(name)).findFirst().orElse(null);
    }

    @Test
    void negativeCountIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> SyntheticScenes.generate(1, -1, Grid.DEFAULT, s -> { }));
    }
}
