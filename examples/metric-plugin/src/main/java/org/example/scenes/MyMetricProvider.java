package org.example.scenes;

import java.util.Map;
import org.scenes.api.MetricProvider;
import org.scenes.api.ObjectKind;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginException;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.api.SeenObject;

/**
 * {@code my-metric}: how far apart the ball is in two scenes, in metres, seen from the player;
 * a scene where the ball is not seen costs the {@code missing} option instead. Rename it and
 * change {@link #distance} to try your own idea.
 */
public final class MyMetricProvider implements MetricProvider {
    @Override
    public String name() {
        return "my-metric";
    }

    @Override
    public String description() {
        return "distance between the ball's positions in the two scenes (template plugin)";
    }

    @Override
    public Map<String, String> options() {
        return Map.of("missing", "cost when only one of the scenes sees the ball (default 10)");
    }

    @Override
    public SceneMetric create(PluginConfig config) {
        double missing = config.doubleOption("missing", 10);
        if (!(missing >= 0)) {
            throw new PluginException("option missing=" + missing + " must not be negative");
        }
        return (query, stored) -> distance(ball(query), ball(stored), missing);
    }

    static double distance(SeenObject a, SeenObject b, double missing) {
        if (a == null || b == null) {
            return a == b ? 0 : missing;
        }
        double dx = x(a) - x(b);
        double dy = y(a) - y(b);
        return Math.sqrt(dx * dx + dy * dy);
    }

    private static SeenObject ball(Scene scene) {
        for (SeenObject object : scene.objects()) {
            if (object.kind() == ObjectKind.BALL) {
                return object;
            }
        }
        return null;
    }

    /** Ahead of the player, in metres; direction is in degrees, positive to the right. */
    private static double x(SeenObject object) {
        return object.distance() * Math.cos(Math.toRadians(object.direction()));
    }

    private static double y(SeenObject object) {
        return object.distance() * Math.sin(Math.toRadians(object.direction()));
    }
}
