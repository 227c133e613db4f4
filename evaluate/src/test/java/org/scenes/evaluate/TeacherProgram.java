package org.scenes.evaluate;

import java.util.List;
import org.scenes.agent.net.ClientOptions;
import org.scenes.agent.net.PlayerReport;
import org.scenes.agent.net.ServerAddress;
import org.scenes.agent.net.TeamRunner;
import org.scenes.simulator.teacher.Teachers;

/**
 * A built-in teacher as a program of its own, for tests of external shadows: {@code HOST PORT TEAM
 * TEACHER [DIE_AT]} plays one player over UDP; with {@code DIE_AT} it exits (status 3) at the first
 * {@code sense_body} of that cycle or later, as a program that crashes mid-game.
 */
public final class TeacherProgram {
    private TeacherProgram() {
    }

    public static void main(String[] args) throws InterruptedException {
        int dieAt = args.length > 4 ? Integer.parseInt(args[4]) : Integer.MAX_VALUE;
        ClientOptions options = ClientOptions.of(new ServerAddress(args[0], Integer.parseInt(args[1])), args[2]);
        org.scenes.simulator.BrainFactory teacher = Teachers.byName(args[3]);
        org.scenes.simulator.BrainFactory dying = (team, random) -> {
            org.scenes.simulator.Brain brain = teacher.create(team, random);
            return (message, send) -> {
                if (message.startsWith("(sense_body ") && Integer.parseInt(message.split(" ")[1]) >= dieAt) {
                    System.out.println("dying at " + message.split(" ")[1]);
                    System.exit(3);
                }
                brain.receive(message, send);
            };
        };
        List<PlayerReport> reports = new TeamRunner(options, 1, dying, 1, System.err::println).play();
        System.exit(reports.stream().allMatch(r -> r.outcome().ok()) ? 0 : 1);
    }
}
