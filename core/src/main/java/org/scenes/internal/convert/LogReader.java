package org.scenes.internal.convert;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Arrays;
import org.scenes.internal.files.Inputs;
import org.scenes.internal.files.IoErrors;
import org.scenes.internal.proxylog.Direction;
import org.scenes.internal.proxylog.MessageEscapes;
import org.scenes.internal.proxylog.ProxyLogLine;

/**
 * Streams the messages of one player log, whatever its {@link LogFormat} (detected from the first
 * line; gzip is read transparently). Never holds more than one line: {@link #next()} moves to the
 * next message, whose bytes are {@code buffer()[offset(), offset() + length())} until the next call.
 * A line whose frame (time, direction) is broken is still returned, with {@link #problem()} set.
 */
public final class LogReader implements AutoCloseable {
    /**
     * The longest line read, in bytes: far above any message the server sends (8 KiB) even
     * escaped, and low enough that a file with no line ends (e.g. {@code /dev/zero}) stops at once.
     */
    public static final int MAX_LINE_BYTES = 1 << 20;
    private final Path file;
    private final InputStream in;
    private final LogFormat format;
    private final byte[] chunk = new byte[1 << 16];
    private int chunkPos;
    private int chunkLength;
    private boolean endOfInput;
    private byte[] line = new byte[1 << 13];
    private int lineLength;
    private boolean firstLinePending;
    private byte[] unescaped = new byte[1 << 13];
    private long lineNumber;
    private long bytesRead;

    private byte[] messageBuffer;
    private int messageOffset;
    private int messageLength;
    private Direction direction;
    private double time = Double.NaN;
    private String problem;
    private byte[] clientPort;

    private LogReader(Path file, InputStream in) throws IOException {
        this.file = file;
        this.in = in;
        while (readLine()) {
            if (!isBlank()) {
                LogFormat detected = LogFormat.detect(line, lineLength);
                if (detected == null) {
                    String first = new String(line, 0, Math.min(lineLength, 60), StandardCharsets.UTF_8);
                    throw new LogException(file, lineNumber, "not a player log (expected an .lsf line '(...)', '"
                            + ProxyLogLine.HEADER + "' or a capture line '<time> client->server <port> (...)'),"
                            + " found: " + first, null);
                }
                this.format = detected;
                this.firstLinePending = detected != LogFormat.NATIVE;
                return;
            }
        }
        this.format = LogFormat.LSF;
    }

    /** Opens a log (plain or gzip) and detects its format; an unknown format is a {@link LogException}. */
    public static LogReader open(Path file) {
        InputStream in;
        try {
            in = Inputs.open(file);
        } catch (NoSuchFileException e) {
            throw new LogException(file, 0, "no such file", e);
        } catch (IOException e) {
            throw new LogException(file, 0, "cannot open: " + IoErrors.reason(e), e);
        }
        try {
            return new LogReader(file, in);
        } catch (Inputs.CorruptCompressionException e) {
            closeQuietly(in);
            throw new LogException(file, 0, e.reason(), e);
        } catch (IOException e) {
            closeQuietly(in);
            throw new LogException(file, 0, "cannot read: " + e.getMessage(), e);
        } catch (RuntimeException e) {
            closeQuietly(in);
            throw e;
        }
    }

    /**
     * Reads a log from a stream that is already decompressed (e.g. text held in memory); {@code name}
     * is used in errors only.
     */
    public static LogReader read(Path name, InputStream in) {
        try {
            return new LogReader(name, in);
        } catch (IOException e) {
            throw new LogException(name, 0, "cannot read: " + e.getMessage(), e);
        }
    }

    public Path file() {
        return file;
    }

    public LogFormat format() {
        return format;
    }

    /** Moves to the next message; false at the end of the log. */
    public boolean next() throws IOException {
        while (true) {
            if (firstLinePending) {
                firstLinePending = false;
            } else if (!readLine()) {
                return false;
            }
            if (isBlank()) {
                continue;
            }
            problem = null;
            String nul = nulProblem();
            if (nul != null) {
                return broken(nul);
            }
            boolean message = switch (format) {
                case LSF -> lsf();
                case NATIVE -> proxy();
                case CAPTURE -> capture();
            };
            if (message) {
                return true;
            }
        }
    }

    public byte[] buffer() {
        return messageBuffer;
    }

    public int offset() {
        return messageOffset;
    }

    public int length() {
        return messageLength;
    }

    /** The current message as text (for errors and tests; the hot path uses the bytes). */
    public String text() {
        return new String(messageBuffer, messageOffset, messageLength, StandardCharsets.UTF_8);
    }

    /** Which way the message travelled, or null when the log does not say (lsf) or its frame is broken. */
    public Direction direction() {
        return direction;
    }

    /** Seconds as the log states them, {@code NaN} for formats without time. */
    public double time() {
        return time;
    }

    /** 1-based line number of the current message. */
    public long line() {
        return lineNumber;
    }

    /** Why the current line's frame is broken, or null when it is fine. */
    public String problem() {
        return problem;
    }

    /** Uncompressed bytes of log text read so far. */
    public long bytesRead() {
        return bytesRead;
    }

    @Override
    public void close() {
        closeQuietly(in);
    }

    // ---- formats ----------------------------------------------------------------------------

    private boolean lsf() {
        setMessage(line, 0, lineLength);
        direction = null;
        return true;
    }

    private boolean proxy() {
        if (line[0] == '#') {
            return false;
        }
        // the native format has one reader of its frame, ProxyLogLine's
        ProxyLogLine.Frame frame = ProxyLogLine.frame(line, lineLength);
        if (frame.problem() != null) {
            return broken(frame.problem());
        }
        direction = frame.direction();
        time = frame.seconds();
        unescape(frame.messageStart());
        return messageLength > 0; // an empty datagram carries no message
    }

    private boolean capture() {
        int firstSpace = LogFormat.indexOf(line, 0, lineLength, (byte) ' ');
        int secondSpace = firstSpace < 0 ? -1 : LogFormat.indexOf(line, firstSpace + 1, lineLength, (byte) ' ');
        int thirdSpace = secondSpace < 0 ? -1 : LogFormat.indexOf(line, secondSpace + 1, lineLength, (byte) ' ');
        if (thirdSpace < 0 || !LogFormat.isDecimal(line, 0, firstSpace)) {
            return broken("expected '<time> <client->server|server->client> <port> <message>'");
        }
        if (LogFormat.startsWith(line, firstSpace + 1, secondSpace, "client->server")) {
            direction = Direction.CLIENT_TO_SERVER;
        } else if (LogFormat.startsWith(line, firstSpace + 1, secondSpace, "server->client")) {
            direction = Direction.SERVER_TO_CLIENT;
        } else {
            return broken("direction must be client->server or server->client");
        }
        if (clientPort == null) {
            clientPort = Arrays.copyOfRange(line, secondSpace + 1, thirdSpace);
        } else if (!Arrays.equals(clientPort, 0, clientPort.length, line, secondSpace + 1, thirdSpace)) {
            // one log is one player: mixing two clients' traffic would pair one's sees with the other's actions
            return broken("a second client (port " + new String(line, secondSpace + 1, thirdSpace - secondSpace - 1,
                    StandardCharsets.UTF_8) + ", first was " + new String(clientPort, StandardCharsets.UTF_8)
                    + "); split the capture by client port");
        }
        time = ProxyLogLine.decimal(line, 0, firstSpace);
        setMessage(line, thirdSpace + 1, lineLength - thirdSpace - 1);
        return true;
    }

    private boolean broken(String why) {
        problem = why;
        direction = null;
        setMessage(line, 0, lineLength);
        return true;
    }

    private void setMessage(byte[] bytes, int offset, int length) {
        while (length > 0 && (bytes[offset + length - 1] == 0 || bytes[offset + length - 1] == ' ')) {
            length--;
        }
        messageBuffer = bytes;
        messageOffset = offset;
        messageLength = length;
    }

    /** Undoes the proxy's escaping when the message has any; a bad escape makes the line malformed. */
    private void unescape(int from) {
        if (LogFormat.indexOf(line, from, lineLength, (byte) '\\') < 0) {
            setMessage(line, from, lineLength - from);
            return;
        }
        if (unescaped.length < lineLength) {
            unescaped = new byte[line.length];
        }
        try {
            setMessage(unescaped, 0, MessageEscapes.unescape(line, from, lineLength, unescaped));
        } catch (IllegalArgumentException e) {
            problem = "bad escape in the message, " + e.getMessage();
            setMessage(line, from, lineLength - from);
        }
    }

    // ---- lines ------------------------------------------------------------------------------

    /**
     * NUL bytes are no part of any message: the server ends a datagram with one, which captures
     * keep after the closing parenthesis; a NUL anywhere else (or a line of them) is a broken line.
     */
    private String nulProblem() {
        int end = lineLength;
        while (end > 0 && line[end - 1] == 0) {
            end--;
        }
        if (end < lineLength && (end == 0 || line[end - 1] != ')')) {
            return "NUL byte at column " + (end + 1);
        }
        int nul = LogFormat.indexOf(line, 0, end, (byte) 0);
        return nul < 0 ? null : "NUL byte at column " + (nul + 1);
    }

    private boolean isBlank() {
        for (int i = 0; i < lineLength; i++) {
            byte c = line[i];
            if (c != ' ' && c != '\t') {
                return false;
            }
        }
        return true;
    }

    /** Reads the next line without its terminator into {@code line}; false at the end of input. */
    private boolean readLine() throws IOException {
        lineLength = 0;
        boolean any = false;
        while (true) {
            if (chunkPos == chunkLength) {
                if (endOfInput) {
                    break;
                }
                int read = in.read(chunk);
                if (read <= 0) {
                    endOfInput = true;
                    break;
                }
                chunkPos = 0;
                chunkLength = read;
                bytesRead += read;
            }
            any = true;
            int i = chunkPos;
            byte[] c = chunk;
            int limit = chunkLength;
            while (i < limit && c[i] != '\n') {
                i++;
            }
            append(chunkPos, i);
            if (i < limit) {
                chunkPos = i + 1;
                lineNumber++;
                trimCarriageReturn();
                return true;
            }
            chunkPos = limit;
        }
        if (!any) {
            return false;
        }
        lineNumber++;
        trimCarriageReturn();
        return true;
    }

    private void append(int from, int to) throws IOException {
        int count = to - from;
        if (lineLength + count > MAX_LINE_BYTES) {
            throw new LogException(file, lineNumber + 1, "line longer than " + MAX_LINE_BYTES
                    + " bytes, the longest a log line may be; is this a player log?", null);
        }
        if (lineLength + count > line.length) {
            byte[] bigger = new byte[Math.max(line.length * 2, lineLength + count)];
            System.arraycopy(line, 0, bigger, 0, lineLength);
            line = bigger;
        }
        System.arraycopy(chunk, from, line, lineLength, count);
        lineLength += count;
    }

    private void trimCarriageReturn() {
        if (lineLength > 0 && line[lineLength - 1] == '\r') {
            lineLength--;
        }
    }

    private static void closeQuietly(InputStream in) {
        try {
            in.close();
        } catch (IOException e) {
            // reading only: nothing can be lost
        }
    }
}
