package org.scenes.internal.convert;

import org.scenes.api.Observer;
import org.scenes.internal.vision.Fading;
import org.scenes.internal.vision.SeeWriter;

/**
 * A player of a game log being rebuilt: its log being converted and how it sees. Made by the
 * reading thread; touched by its worker only once started.
 */
final class RebuiltPlayer {
    final Observer observer;
    final String key;
    final SceneConverter.SceneSink sink;
    final RebuildWorker worker;
    final int version;
    final Fading fading;
    /** Whether the game log marks the player as its team's goalie (at its first show). */
    boolean goalie;
    /** Set by the reading thread when the player's first show is handed out. */
    boolean started;
    /** The play mode the player was last told (world models only). */
    String heardMode;
    SceneConverter.Feed feed;
    SeeWriter writer;
    boolean synchSee;
    /**
     * Where the player's asynchronous see clock starts, in ms from the first step's start; set by
     * the reading thread before the player's first step is handed out.
     */
    double seeOffset;
    int type = -1;
    /** The executed command counts at the last show, and whether a body command was sent since. */
    int executed = -1;
    boolean sentBody;
    /** The steps of the player's last see and last command, to order the two within a step. */
    long seeStep = -1;
    long commandStep = -1;
    long agreed;
    long disagreed;

    RebuiltPlayer(Observer observer, String key, SceneConverter.SceneSink sink, RebuildWorker worker, int version,
                  boolean synchSee, double seeOffset, Fading fading) {
        this.seeOffset = seeOffset;
        this.observer = observer;
        this.key = key;
        this.sink = sink;
        this.worker = worker;
        this.version = version;
        this.synchSee = synchSee;
        this.fading = fading;
    }
}
