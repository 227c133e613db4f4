package org.scenes.api;

/** The half a team starts in: left defends x = -52.5, right defends x = 52.5. */
public enum Side {
    /** The left team, {@code l} in the protocol. */
    LEFT('l'),
    /** The right team, {@code r} in the protocol. */
    RIGHT('r');

    private final char letter;

    Side(char letter) {
        this.letter = letter;
    }

    /**
     * The protocol's letter for the side.
     *
     * @return {@code l} or {@code r}
     */
    public char letter() {
        return letter;
    }

    /**
     * The other side.
     *
     * @return right for left, left for right
     */
    public Side opposite() {
        return this == LEFT ? RIGHT : LEFT;
    }

    /**
     * The side of a protocol letter.
     *
     * @param letter {@code l} or {@code r}
     * @return the side; another letter is an {@code IllegalArgumentException}
     */
    public static Side fromLetter(char letter) {
        switch (letter) {
            case 'l': return LEFT;
            case 'r': return RIGHT;
            default: throw new IllegalArgumentException("side must be 'l' or 'r', not '" + letter + "'");
        }
    }
}
