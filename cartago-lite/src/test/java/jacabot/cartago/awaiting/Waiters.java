package jacabot.cartago.awaiting;

import jacabot.cartago.Artifact;
import jacabot.cartago.GUARD;
import jacabot.cartago.OPERATION;
import java.util.ArrayList;
import java.util.List;

/** Operations that wait in every way code can reach an await, and some that never do (AwaitAnalysisTest). */
public class Waiters extends Artifact {
    final List<String> done = new ArrayList<>();

    void init() {
        defineObsProperty("n", 0);
    }

    @OPERATION
    void plain(int k) {
        done.add("plain");
        getObsProperty("n").updateValue(k + helper());
        signal("tick");
    }

    @OPERATION
    void withLoop(int k) {
        for (int i = 0; i < k; i++) {
            done.add(String.valueOf(i));
        }
        done.forEach(String::length); // a method reference to foreign code
    }

    @OPERATION
    void direct() {
        await_time(5);
    }

    @OPERATION
    void throughHelper() {
        pauseALittle();
    }

    @OPERATION
    void throughLambda() {
        Runnable r = () -> await_time(5);
        r.run();
    }

    @OPERATION
    void throughInnerClass() {
        new Runnable() {
            @Override
            public void run() {
                await_time(5);
            }
        }.run();
    }

    @OPERATION
    void throughPackageHelper() {
        SamePackageHelper.pause(this);
    }

    @OPERATION
    void linked() {
        execLinkedOp("out", "op");
    }

    @OPERATION
    void blocking() {
        await(() -> { });
    }

    @OPERATION(guard = "ready")
    void guarded() {
        done.add("guarded");
    }

    @GUARD
    boolean ready() {
        return true;
    }

    @OPERATION
    void overridden() {
        done.add("base");
    }

    private int helper() {
        return 1;
    }

    private void pauseALittle() {
        await_time(1);
    }

    /** Only for the package helper: a protected primitive reached from outside the artifact. */
    void pauseFromOutside() {
        await_time(1);
    }
}
