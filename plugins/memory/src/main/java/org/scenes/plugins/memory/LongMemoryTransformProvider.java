package org.scenes.plugins.memory;

import org.scenes.api.PluginConfig;
import org.scenes.api.Scene;
import org.scenes.api.SceneTransform;
import org.scenes.api.TransformProvider;

/**
 * {@code long-memory}: as {@code memory}, and the remembered scene carries the actions of the
 * player's scenes before it, {@link Scene#MAX_MEMORY} in all, without their objects, for the
 * object-set metrics' {@code memory-depth}. Apart so that {@code memory} stores no more than it did.
 */
public final class LongMemoryTransformProvider implements TransformProvider {
    @Override
    public String name() {
        return "long-memory";
    }

    @Override
    public String description() {
        return "each scene remembers the previous scene, and the actions of the player's last " + Scene.MAX_MEMORY + " scenes";
    }

    @Override
    public SceneTransform create(PluginConfig config) {
        return new MemoryTransformProvider.Memory(true);
    }
}
