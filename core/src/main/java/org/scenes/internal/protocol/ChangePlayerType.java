package org.scenes.internal.protocol;

/** {@code (change_player_type UNUM [TYPE])}: a teammate's new type, or an opponent's change (type -1). */
public record ChangePlayerType(int uniformNumber, int type) implements Message {
    @Override
    public String head() {
        return "change_player_type";
    }
}
