package org.scenes.cli;

import java.nio.file.Path;
import java.util.List;
import org.scenes.agent.imitation.ImitationBrain;
import org.scenes.agent.imitation.ImitationTeam;
import org.scenes.agent.imitation.Viewing;
import org.scenes.api.PluginRegistry;
import org.scenes.evaluate.ClockPacedBrain;
import org.scenes.evaluate.PacedBrain;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.simulator.BrainFactory;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Option;
import picocli.CommandLine.TypeConversionException;

/** {@code --knowledge}, {@code --think-steps} and {@code --think-millis}: how an imitation team ({@code play}, {@code match}) is assembled. */
final class ImitationTeamOptions {
    @Option(names = "--knowledge", paramLabel = "counterpart|team", defaultValue = "counterpart",
            converter = KnowledgeConverter.class,
            description = {"Whose scenes each imitating player matches: counterpart (the recorded player with its"
                    + " uniform number, the team's when there is none; default) or team (everyone's). Either way a"
                    + " player takes its counterpart's kick-off moves and inits as goalie when it was the goalie."})
    ImitationTeam.Knowledge knowledge;

    @Option(names = "--think-steps", paramLabel = "N", defaultValue = "0",
            description = "Imitators decide on the latest see every N steps (Krislet's think loop: 2); 0: every see"
                    + " (the scenes' own tempo). Default: ${DEFAULT-VALUE}.")
    int thinkSteps;

    /** A rest longer than this (a minute) is a typing error, not a tempo. */
    private static final long MAX_THINK_MILLIS = 60_000;

    @Option(names = "--think-millis", paramLabel = "MS", defaultValue = "0",
            description = "Imitators rest MS milliseconds of wall time after each decision, then decide on the"
                    + " next see (the classic Krislet client's 200 ms sleep); for real-time servers only. Not with"
                    + " --think-steps. Default: ${DEFAULT-VALUE} (off).")
    long thinkMillis;

    /** The team from the scene files, on the configuration's matching. */
    ImitationTeam load(List<Path> files, MatchConfig config, PluginRegistry registry) {
        if (thinkSteps < 0) {
            throw new UsageException("--think-steps: must be 0 or more, not " + thinkSteps);
        }
        if (thinkMillis < 0 || thinkMillis > MAX_THINK_MILLIS) {
            throw new UsageException("--think-millis: must be 0 to " + MAX_THINK_MILLIS + ", not " + thinkMillis);
        }
        if (thinkMillis > 0 && thinkSteps > 0) {
            throw new UsageException("--think-millis and --think-steps: give one tempo, not both");
        }
        return ImitationTeam.load(files, config.transformFactory(registry),
                knowledgeBase -> config.recognizer(knowledgeBase, registry, config.k()), knowledge);
    }

    /** In the embedded simulator the steps do not follow the clock: a wall-clock tempo is a usage error there. */
    void requireNoClockTempo() {
        if (thinkMillis != 0) {
            throw new UsageException("--think-millis: only for a real-time server (--server); in the embedded simulator"
                    + " the steps do not follow the clock (--think-steps paces by steps)");
        }
    }

    /** The players' brains, paced when asked. */
    BrainFactory brains(ImitationTeam team, MatchConfig config, PluginRegistry registry, ImitationBrain.Guards guards) {
        BrainFactory brains = team.brains(config.selectorFactory(registry), config.transformFactory(registry), guards,
                config.replay());
        return Viewing.with(ClockPacedBrain.pace(PacedBrain.pace(brains, thinkSteps), thinkMillis), config.view());
    }

    static final class KnowledgeConverter implements ITypeConverter<ImitationTeam.Knowledge> {
        @Override
        public ImitationTeam.Knowledge convert(String value) {
            ImitationTeam.Knowledge knowledge = ImitationTeam.Knowledge.fromKey(value);
            if (knowledge == null) {
                throw new TypeConversionException("expected counterpart or team, not '" + value + "'");
            }
            return knowledge;
        }
    }
}
