package org.scenes.internal.protocol;

import java.util.Arrays;
import java.util.Locale;
import java.util.stream.Collectors;

/**
 * The view widths of {@code (change_view WIDTH)}: narrow (60°), normal (120°) and wide (180°). On
 * synchronous vision ({@code (synch_see)}) a narrow view sees every step, a normal one every second
 * and a wide one every third.
 */
public enum ViewWidth {
    NARROW(60), NORMAL(120), WIDE(180);

    private final double degrees;

    ViewWidth(double degrees) {
        this.degrees = degrees;
    }

    /** The view's angle in degrees, centred on the head. */
    public double degrees() {
        return degrees;
    }

    /** The width of this name (as {@code sense_body} reports it), or null. */
    public static ViewWidth fromKey(String key) {
        for (ViewWidth width : values()) {
            if (width.key().equals(key)) {
                return width;
            }
        }
        return null;
    }

    /** The protocol's name, also the one in configuration files. */
    public String key() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The command that asks the server for this width (the quality stays high). */
    public String command() {
        return "(change_view " + key() + ")";
    }

    /**
     * @throws IllegalArgumentException naming the accepted values
     */
    public static ViewWidth parse(String text) {
        ViewWidth width = fromKey(text);
        if (width != null) {
            return width;
        }
        throw new IllegalArgumentException("unknown view '" + text + "': use one of "
                + Arrays.stream(values()).map(ViewWidth::key).collect(Collectors.joining(", ")));
    }
}
