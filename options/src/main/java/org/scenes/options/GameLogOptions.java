package org.scenes.options;

import java.util.function.Predicate;
import org.scenes.api.Observer;
import org.scenes.internal.convert.GameLogConverter;
import org.scenes.internal.vision.Fading;
import picocli.CommandLine.Option;

/** How the server's game logs become scenes: the players chosen, the fading, the order of commands and sees. */
public final class GameLogOptions {
    @Option(names = "--team", paramLabel = "NAME", description = "Game logs: only this team's players.")
    private String team;

    @Option(names = "--unum", paramLabel = "N", description = "Game logs: only players with this number.")
    private int unum;

    @Option(names = "--fading", paramLabel = "dice|halfway", defaultValue = "dice",
            description = {"Game logs: how a seen player's team and number (and changes) fade with distance: dice"
                    + " (the server's probabilities; default) or halfway (shown below the halfway point, as the"
                    + " simulator does)."})
    private String fading;

    @Option(names = "--fading-seed", paramLabel = "N", defaultValue = "1", description = "Game logs: seed of the"
            + " fading dice. Default: 1.")
    private long fadingSeed;

    @Option(names = "--commands-first", description = {"Game logs: within a step, a player's commands came"
            + " before its see. Default: before it only when the player already had a see taken after its last"
            + " command, otherwise after it."})
    private boolean commandsFirst;

    @Option(names = "--see-phase", paramLabel = "infer|first-step", defaultValue = "infer",
            description = {"Game logs: where an asynchronous player's see clock starts: infer (as rcssserver's,"
                    + " at the player's connection: from its init's step and when its commands came; default) or"
                    + " first-step (multiples of the see period from the first step, as the project's simulator"
                    + " keeps it)."})
    private String seePhase;

    /** The team chosen, null for both. */
    public String team() {
        return team;
    }

    /** The uniform number chosen, 0 for any. */
    public int unum() {
        return unum;
    }

    public String fadingName() {
        return fading;
    }

    public long fadingSeed() {
        return fadingSeed;
    }

    public boolean commandsFirst() {
        return commandsFirst;
    }

    /** The see phase the options name. */
    public GameLogConverter.SeePhase seePhase() {
        return switch (seePhase) {
            case "infer" -> GameLogConverter.SeePhase.INFER;
            case "first-step" -> GameLogConverter.SeePhase.FIRST_STEP;
            default -> throw new OptionException("--see-phase: expected infer or first-step, not '" + seePhase + "'");
        };
    }

    /**
     * Checks the options: the fading is known and the number one of a team's.
     *
     * @throws OptionException naming the option
     */
    public void check() {
        fading();
        seePhase();
        if (unum < 0 || unum > 11) {
            throw new OptionException("--unum: a uniform number from 1 to 11, not " + unum);
        }
    }

    /** The fading the options name. */
    public Fading fading() {
        Fading named = Fading.named(fading, fadingSeed);
        if (named == null) {
            throw new OptionException("--fading: expected dice or halfway, not '" + fading + "'");
        }
        return named;
    }

    /** The players the options choose. */
    public Predicate<Observer> selected() {
        return GameLogConverter.only(team, unum);
    }

    /** The error when no player of a game matches the choice. */
    public String noPlayer(Object gameLog) {
        return noPlayer(gameLog, team, unum);
    }

    /** The error when no player of a game is of {@code team} (any when null) with number {@code unum} (any when 0). */
    public static String noPlayer(Object gameLog, String team, int unum) {
        return "no player of " + gameLog + " is " + (team == null ? "" : "of team " + team + " ")
                + (unum == 0 ? "" : "number " + unum);
    }
}
