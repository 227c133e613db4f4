package org.scenes.api;

/**
 * One of the k stored scenes nearest to a query.
 *
 * @param scene the stored scene
 * @param index its position in the knowledge base (ties are broken by it)
 * @param distance its distance from the query
 */
public record Neighbour(Scene scene, int index, double distance) {
}
