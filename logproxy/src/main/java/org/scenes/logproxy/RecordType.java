package org.scenes.logproxy;

/** Kinds of records in the {@link LogRing}; ints so the ring stays a plain byte array. */
final class RecordType {
    /** A client datagram forwarded to the server; payload = datagram without NUL padding. */
    static final int TO_SERVER = 1;
    /** A server datagram forwarded to the client. */
    static final int TO_CLIENT = 2;
    /** A new client; payload = "KIND address". */
    static final int OPEN = 3;
    /** The client's session ended; payload = reason. */
    static final int CLOSE = 4;
    /** Something worth a comment in the log; payload = text. */
    static final int NOTE = 5;

    private RecordType() {
    }
}
