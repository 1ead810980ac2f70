// Messages that fail or wait: a receiver that does not exist, asks to many, late answers, ids
v(1).
v(2).
!start.
+!start
    <- !unknown_receiver;
       !unknown_in_list;
       !ask_to_many;
       !ask_to_many_timeout;
       !answer_not_unifying;
       !answer_not_unifying_last;
       !late_answer;
       !ask_ids;
       .print(function_unground(.length([a, X])), " ", function_ground(.length([a, b])));
       .print(end);
       .stopMAS.

+!unknown_receiver <- .send(nobody, tell, x(1, "s")).
-!unknown_receiver[error(E), error_msg(M), agent_not_found(N)] <- .print(failed(E, N)); .print(M).

+!unknown_in_list <- .send([self, nobody2], tell, w(1)); .print(not_here).
-!unknown_in_list[error(E), agent_not_found(N)] <- .findall(X, w(X), L); .print(list_failed(E, N, L)).

+!ask_to_many <- .send([self, self], askOne, v(X), L); .print(many(L));
                 .send([self, self], askAll, v(Y), L2); .print(many_all(L2)).

+!ask_to_many_timeout <- .send([self, self], askOne, slow(X), L, 400); .print(many_timeout(L)).
+?slow(X) <- .wait(200); X = 1.

+!answer_not_unifying <- .send(self, askOne, v(_), 5); .print(after_send).
-!answer_not_unifying[error(E), error_msg(M), code(C)] <- .print(E, " ", C); .print(M).

+!answer_not_unifying_last <- .send(self, askOne, v(_), 7).
-!answer_not_unifying_last[error(E)] <- .print(annotated(E)).
-!answer_not_unifying_last <- .print(no_annotations).

+!late_answer <- .send(self, askOne, slower(X), A, 100); .print(late(A)); .wait(700); .findall(S, slower(S), L); .print(late_beliefs(L)).
+?slower(X) <- .wait(400); X = 2.

+!ask_ids <- .send(self, askOne, v(X)); .wait(50); .send(self, tell, t(1)); .send(self, askOne, v(Y), A); .wait(100); .print(ids_done).
+!kqml_received(S, P, C, M) : P \== askOne & P \== askAll <- .print(kqml(S, P, C, M)).
+t(X)[source(S)] <- .print(told(X, S)).
