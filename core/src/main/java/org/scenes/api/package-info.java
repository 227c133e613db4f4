/**
 * The scenes plugin API: everything a metric, selector or transform plugin needs, and the only
 * package of {@code core} a plugin may depend on. Every other package is
 * {@code org.scenes.internal.*}: public for the project's own modules, free to change without notice.
 *
 * <h2>Writing a plugin</h2>
 * <ol>
 * <li>Implement a service interface: {@link org.scenes.api.MetricProvider} (makes a
 *     {@link org.scenes.api.SceneMetric}), {@link org.scenes.api.SelectorProvider} (makes an
 *     {@link org.scenes.api.ActionSelector}) or {@link org.scenes.api.TransformProvider} (makes a
 *     {@link org.scenes.api.SceneTransform}). Each is a {@link org.scenes.api.NamedProvider}: a short
 *     name users type, a description, and the options it accepts.</li>
 * <li>Name the class in {@code META-INF/services/org.scenes.api.MetricProvider} (or the selector's or
 *     transform's interface) and put the jar in a plugin directory; {@code scenes plugins} lists it.</li>
 * <li>Configuration arrives as a {@link org.scenes.api.PluginConfig}: object and action weights,
 *     the checked options, a seed, the argument after {@code name:}. Refuse bad values with a
 *     {@link org.scenes.api.PluginException} whose message says what to do.</li>
 * </ol>
 *
 * <h2>What a plugin reads</h2>
 * A {@link org.scenes.api.Scene} is what one player saw in one cycle ({@link org.scenes.api.SeenObject}s
 * of an {@link org.scenes.api.ObjectKind}, with their {@link org.scenes.api.Relation} to the
 * {@link org.scenes.api.Observer} and their {@link org.scenes.api.Cell} of the {@link org.scenes.api.Grid})
 * and what it did ({@link org.scenes.api.Action}s of an {@link org.scenes.api.ActionType}). A selector
 * gets the nearest stored scenes as {@link org.scenes.api.Neighbour}s.
 *
 * <h2>Building on the project's own pieces</h2>
 * {@link org.scenes.api.ObjectSetMetrics} builds the object-set metric that {@code continuous},
 * {@code cell} and {@code projection} are made of; {@link org.scenes.api.EncodedMetric} and
 * {@link org.scenes.api.PackedMetric} (with {@link org.scenes.api.TopK}) are the fast paths a metric
 * may offer; {@link org.scenes.api.NearestScenes} searches scenes held in memory as the imitating
 * agent does; {@link org.scenes.api.ActionLabel} names the classes results are scored by.
 * {@link org.scenes.api.PluginRegistry} finds providers by name, typed
 * ({@link org.scenes.api.PluginRegistry#provider}), as a plugin's tests may.
 */
package org.scenes.api;
