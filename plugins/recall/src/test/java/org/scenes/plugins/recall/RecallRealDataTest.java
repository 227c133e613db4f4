package org.scenes.plugins.recall;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.scenes.api.Grid;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;
import org.scenes.api.SceneTransform;
import org.scenes.api.SeenObject;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.testing.RequiresSharedData;
import org.scenes.testing.SharedData;

class RecallRealDataTest {
    @Test
    @RequiresSharedData
    void aRealGameRemembersOutOfViewObjectsOnceEachAndKeepsWhatWasSeen() throws IOException {
        List<Scene> scenes = new ArrayList<>();
        SceneConverter.with(Grid.DEFAULT).build()
                .convert(SharedData.resolve("krislet/classic-game2/Carleton_4.lsf.gz"), scenes::add);
        SceneTransform recall = PluginRegistry.load().transform("recall:10", PluginConfig.DEFAULT);
        long rememberedBalls = 0;
        long scenesWithoutBall = 0;
        for (Scene scene : scenes) {
            Scene recalled = recall.apply(scene);
            assertEquals(scene.objects(), recalled.objects().subList(0, scene.objects().size()), "seen objects first, unchanged");
            Set<String> identities = new HashSet<>();
            for (SeenObject object : recalled.objects().subList(scene.objects().size(), recalled.objects().size())) {
                assertTrue(object.remembered());
                assertTrue(identities.add(object.identity()), "remembered once: " + object.identity());
                assertTrue(object.direction() < -45 || object.direction() > 45 || object.distance() <= 3,
                        "a remembered object lies out of view: " + object);
            }
            boolean seesBall = scene.objects().stream().anyMatch(o -> o.kind() == org.scenes.api.ObjectKind.BALL);
            if (!seesBall) {
                scenesWithoutBall++;
                rememberedBalls += recalled.objects().stream()
                        .filter(o -> o.kind() == org.scenes.api.ObjectKind.BALL && o.remembered()).count();
            }
        }
        // the player loses the ball on its right and turns away from it: for a while it is remembered
        assertTrue(rememberedBalls > 0 && rememberedBalls < scenesWithoutBall,
                rememberedBalls + " remembered balls in " + scenesWithoutBall + " scenes without a ball");
    }
}
