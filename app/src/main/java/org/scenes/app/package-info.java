/**
 * The application layer: each workflow of the {@code scenes} tools as a service that takes a typed
 * request, reports progress through {@link org.scenes.app.Progress} and returns a result, so the
 * command line and the Spark jobs only parse options, call a service and print. One package per
 * workflow ({@code org.scenes.app.validate}); none knows of picocli, terminals or Spark.
 */
package org.scenes.app;
