package org.example.scenes;

import org.scenes.api.Action;
import org.scenes.api.ActionSelector;
import org.scenes.api.Neighbour;
import org.scenes.api.PluginConfig;
import org.scenes.api.SelectorProvider;

/** {@code my-selector}: the action of the nearest stored scene that holds one. */
public final class MySelectorProvider implements SelectorProvider {
    @Override
    public String name() {
        return "my-selector";
    }

    @Override
    public String description() {
        return "the action of the nearest neighbour that has one (template plugin)";
    }

    @Override
    public ActionSelector create(PluginConfig config) {
        return (nearest, random) -> {
            for (Neighbour neighbour : nearest) { // nearest first
                Action action = neighbour.scene().primaryAction();
                if (action != null) {
                    return action;
                }
            }
            return null;
        };
    }
}
