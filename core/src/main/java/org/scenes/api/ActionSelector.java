package org.scenes.api;

import java.util.List;
import java.util.random.RandomGenerator;

/** Picks the action to take from the nearest stored scenes, nearest first. */
public interface ActionSelector {
    /**
     * @param nearest the k nearest scenes, nearest first, never empty
     * @param random the only source of randomness allowed, seeded by the caller so runs repeat
     * @return the action to take, or null when no neighbour holds a usable action
     */
    Action select(List<Neighbour> nearest, RandomGenerator random);
}
