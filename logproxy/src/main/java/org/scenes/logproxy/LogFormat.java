package org.scenes.logproxy;

/** Layout of the per-client log files. */
public enum LogFormat {
    /** {@code #scenes-proxy-log 1}: timestamp, direction and escaped message per line. */
    NATIVE("log"),
    /** The classic logging proxy's layout: one message per line, no time, no direction. */
    LSF("lsf");

    private final String extension;

    LogFormat(String extension) {
        this.extension = extension;
    }

    public String extension() {
        return extension;
    }
}
