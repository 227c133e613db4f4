package org.scenes.internal.protocol;

import java.util.List;

/** {@code (see TIME OBJECT...)}: what the player sees, objects in server order. */
public record See(int time, List<VisualObject> objects, List<String> leftovers) implements Message {
    public See {
        objects = List.copyOf(objects);
        leftovers = List.copyOf(leftovers);
    }

    @Override
    public String head() {
        return "see";
    }
}
