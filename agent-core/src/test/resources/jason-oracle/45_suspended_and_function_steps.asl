// A function call written as a plan body formula, and .intend/.desire of suspended intentions
!start.

+!start
   <- !b; !d;
      !!g(1); .wait(50);
      if (.intend(g(_))) { .print(intend_sees_suspended) } else { .print(intend_skips_suspended) };
      if (.desire(g(X))) { .print(desire_sees_suspended(X)) } else { .print(desire_skips_suspended) };
      .findall(I, .intend(start, I), Ids); .length(Ids, NIds); .print(start_intended_times(NIds));
      .intend(start, Id); .print(id_is_number(.number(Id)));
      .findall(G, .intend(G), Gs); .print(intended(Gs));
      .resume(g(1)); .wait(50);
      if (.intend(g(_))) { .print(intend_after_resume) } else { .print(no_intend_after_resume) };
      .print(done);
      .stopMAS.

+!b <- math.median([1,a]); .print(after_b).
-!b[error(E),error_msg(M),code(C),code_line(L)] <- .print(failed_b(E,C,L)); .print(M).
+!d <- X = 1; math.median([]); .print(after_d).
-!d[error(E),error_msg(M)|T] <- .print(failed_d(E,T)); .print(M).

+!g(N) <- .suspend; .print(resumed(N)); .wait(1000).
