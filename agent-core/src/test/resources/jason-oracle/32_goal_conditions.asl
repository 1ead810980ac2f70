// Goal conditions (Jason 3.2's "<:"): a goal ends, achieved, as soon as its condition holds.
!start.

+!start
   <- !a; .print(after_a);
      !b; .print(after_b);
      !!set_later(ready_c, 100); !c; .print(after_c);
      !d; .print(after_d);
      !!set_later(stop_e, 100); !e; .print(after_e);
      !f; .print(after_f);
      !h(2); .print(after_h);
      !k; .print(after_k);
      !!set_later(w_done, 50); !w; .print(after_w);
      !!m; .wait(100); .print(after_m);
      .relevant_plans({+!b}, L); .print(L);
      .stopMAS.

// a condition that holds at once: the body never runs
+!a <: true <- .print(a_body).

// a condition made true by the body: the rest of the body is dropped
+!b <: done_b <- .print(b1); +done_b; .print(b2); .print(b3).

// a body that ends before its condition holds: the goal waits for it
+!c <: ready_c <- .print(c_body); .print(c_body_end).

// sub-goals are dropped with the goal
+!d <: stop_d <- !d_sub; .print(d_after_sub).
+!d_sub <- .print(d_sub1); +stop_d; .print(d_sub2); .print(d_sub3).

// a sub-goal that ends in a goal with a condition
+!e <: stop_e <- !e_sub; .print(e_after_sub); .print(e_more).
+!e_sub <- .print(e_sub).

// goal states of a goal with a condition
+!f <: f_done <- .print(f1); +f_done; .print(f2).
^!f[state(S)] <- .print(f_state(S)).

// the condition sees the trigger's variables
+!h(N) <: count_h(N) <- for (.range(I, 1, 5)) { -+count_h(I); .print(h(I)) }.

// .succeed_goal of a goal with a condition
+!k <: false <- .print(k1); .succeed_goal(k); .print(k2).

// a goal waiting in .wait ends when its condition holds
+!w <: w_done <- .print(w1); .wait(5000); .print(w2).

// a failure in a goal with a condition: once its failure plan ends, the intention waits for
// the condition (Jason 3.2.0 parks an intention whose stack holds a goal condition)
+!m <: never_m <- .print(m1); .fail; .print(m2).
-!m[error(E)] <- .print(m_failed(E)).
+!m_sub <- .print(m_sub).

+!set_later(B, T) <- .wait(T); +B; .print(set(B)).
