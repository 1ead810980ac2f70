package jacabot.app.cli;

final class TeamSweepCommand {
}
