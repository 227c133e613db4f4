package org.scenes.cli;

import java.util.concurrent.Callable;
import org.scenes.simulator.BrainFactory;
import org.scenes.simulator.teacher.Teachers;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code scenes team --teacher NAME --server HOST:PORT}: a teacher team on a soccer server. */
@Command(name = "team", mixinStandardHelpOptions = false,
        description = {"Play a teacher team (the agents imitators learn from) on a soccer server over UDP, a thread"
                + " per player, until the referee says time_over or Ctrl-C. 'scenes play SCENES... --server' starts an"
                + " imitation team the same way, with the same options. Exit 1 when a player found no server, lost it"
                + " or failed."})
final class TeamCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Option(names = {"-h", "--help"}, usageHelp = true, description = "Show this help message and exit.")
    boolean help;

    @Option(names = "--teacher", paramLabel = "NAME", required = true, description = "The teacher: krislet or statebased.")
    String teacher;

    @Option(names = "--players", paramLabel = "N", defaultValue = "11",
            description = "Players, 1 to 11. Default: ${DEFAULT-VALUE}.")
    int players;

    @Option(names = "--seed", paramLabel = "S", defaultValue = "1",
            description = "Seed of the players' random choices (player i gets S + i). Default: ${DEFAULT-VALUE}.")
    long seed;

    @Mixin
    LiveOptions live;

    @Override
    public Integer call() throws InterruptedException {
        if (live.server == null) {
            throw new UsageException("--server: say which soccer server to play on, e.g. --server 127.0.0.1:6000");
        }
        BrainFactory brains;
        try {
            brains = Teachers.byName(teacher);
        } catch (IllegalArgumentException e) {
            throw new UsageException("--teacher: " + e.getMessage());
        }
        String defaultTeam = Character.toUpperCase(teacher.charAt(0)) + teacher.substring(1);
        return LiveTeam.play(live.clientOptions(defaultTeam), players, brains, seed, live.json,
                spec.commandLine().getOut(), spec.commandLine().getErr());
    }
}
