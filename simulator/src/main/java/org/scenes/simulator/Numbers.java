package org.scenes.simulator;

import org.scenes.internal.vision.VisionNumbers;

/** Quantisation and number text as the server writes them (shared with core's vision: {@link VisionNumbers}). */
final class Numbers {
    private Numbers() {
    }

    static double quantize(double value, double step) {
        return VisionNumbers.quantize(value, step);
    }

    static double seenDistance(double distance, double step) {
        return VisionNumbers.seenDistance(distance, step);
    }

    static double normalize(double degrees) {
        return VisionNumbers.normalize(degrees);
    }

    static String formatChange(double value, int decimals) {
        return VisionNumbers.formatChange(value, decimals);
    }

    static String format(double value, int decimals) {
        return VisionNumbers.format(value, decimals);
    }
}
