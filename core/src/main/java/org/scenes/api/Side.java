package org.scenes.api;

/** The half a team starts in: left defends x = -52.5, right defends x = 52.5. */
public enum Side {
    LEFT('l'), RIGHT('r');

    private final char letter;

    Side(char letter) {
        this.letter = letter;
    }

    public char letter() {
        return letter;
    }

    public Side opposite() {
        return this == LEFT ? RIGHT : LEFT;
    }

    public static Side fromLetter(char letter) {
        switch (letter) {
            case 'l': return LEFT;
            case 'r': return RIGHT;
            default: throw new IllegalArgumentException("side must be 'l' or 'r', not '" + letter + "'");
        }
    }
}
