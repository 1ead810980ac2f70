package jacabot.cartago.awaiting;

/** Overrides a never-waiting operation of its superclass with one that waits. */
public class WaitingSubclass extends Waiters {
    @Override
    void overridden() {
        await_time(1);
    }
}
