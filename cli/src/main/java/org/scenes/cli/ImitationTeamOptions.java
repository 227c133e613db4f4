package org.scenes.cli;

import java.nio.file.Path;
import java.util.List;
import org.scenes.agent.imitation.ImitationBrain;
import org.scenes.agent.imitation.ImitationTeam;
import org.scenes.agent.imitation.Viewing;
import org.scenes.api.PluginRegistry;
import org.scenes.evaluate.PacedBrain;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.simulator.BrainFactory;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Option;
import picocli.CommandLine.TypeConversionException;

/** {@code --knowledge} and {@code --think-steps}: how an imitation team ({@code play}, {@code match}) is assembled. */
final class ImitationTeamOptions {
    @Option(names = "--knowledge", paramLabel = "counterpart|team", defaultValue = "counterpart",
            converter = KnowledgeConverter.class,
            description = {"Whose scenes each imitating player matches: counterpart (the recorded player with its"
                    + " uniform number, the team's when there is none; default) or team (everyone's). Either way a"
                    + " player takes its counterpart's kick-off moves and inits as goalie when it was the goalie."})
    ImitationTeam.Knowledge knowledge;

    @Option(names = "--think-steps", paramLabel = "N", defaultValue = "0",
            description = "Imitators decide on the latest see every N steps (Krislet's think loop: 2; a fraction such"
                    + " as 1.96 decides now and then a step early, as the client does on a real-time server); 0: every"
                    + " see (the scenes' own tempo). Default: ${DEFAULT-VALUE}.")
    double thinkSteps;

    /** --think-steps is 0, or 1 or more. */
    void checkThinkSteps() {
        if (!PacedBrain.valid(thinkSteps)) {
            throw new UsageException("--think-steps: must be 0, or 1 or more, not " + PacedBrain.text(thinkSteps));
        }
    }

    /** The team from the scene files, on the configuration's matching. */
    ImitationTeam load(List<Path> files, MatchConfig config, PluginRegistry registry) {
        checkThinkSteps();
        return ImitationTeam.load(files, config.transformFactory(registry),
                knowledgeBase -> config.recognizer(knowledgeBase, registry, config.k()), knowledge);
    }

    /** The players' brains, paced when asked. */
    BrainFactory brains(ImitationTeam team, MatchConfig config, PluginRegistry registry, ImitationBrain.Guards guards) {
        return Viewing.with(PacedBrain.pace(team.brains(config.selectorFactory(registry),
                config.transformFactory(registry), guards, config.replay()), thinkSteps), config.view());
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
