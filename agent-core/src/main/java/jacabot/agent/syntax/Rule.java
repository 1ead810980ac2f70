package jacabot.agent.syntax;

/** A Prolog-like rule {@code head :- body} of the belief base. */
public record Rule(Literal head, Term body) {
    @Override
    public String toString() {
        return head + " :- " + body;
    }
}
