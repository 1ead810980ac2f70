// jacabot's AgentSpeak test library: the assertions. Each is an achievement goal, as in Jason
// 3.2's test_assert.asl (same names, arguments and console lines; jacabot's code). A passing one
// prints "<assertion> on event '<test>' PASSED", a failing one "<assertion> on event '<test>'
// starting at line <L> FAILED! <why>"; a failed assertion is counted and its test goes on.
// running_test(Goal) is the test under way (set by tester_agent.asl).

@assert_equals_lists[atomic]
+!assert_equals(X, Y) : .list(X) & .list(Y)
    <- if (.difference(X, Y, []) & .difference(Y, X, [])) { !test_passed(assert_equals) }
       else { !equals_failed(X, Y) }.
@assert_equals[atomic]
+!assert_equals(X, Y)
    <- if (X == Y) { !test_passed(assert_equals) } else { !equals_failed(X, Y) }.
+!equals_failed(X, Y)
    <- .type(X, TX); .type(Y, TY);
       !test_failed(assert_equals, ["Expected '", X, "' (", TX, ") but had '", Y, "' (", TY, ")"]).

@assert_equals_tolerance[atomic]
+!assert_equals(X, Y, T)
    <- if (.number(X) & .number(Y) & .number(T) & Y >= X - T & Y <= X + T) { !test_passed(assert_equals) }
       else { .type(X, TX); .type(Y, TY);
              !test_failed(assert_equals, ["Expected '", X, "+/-", T, "' (", TX, "), but had '", Y, "' (", TY, ")"]) }.

@assert_not_equals[atomic]
+!assert_not_equals(X, Y)
    <- if (X \== Y) { !test_passed(assert_not_equals) }
       else { .type(X, TX); .type(Y, TY);
              !test_failed(assert_not_equals, ["Expected '", X, "' (", TX, ") different than '", Y, "' (", TY, ")"]) }.

@assert_true[atomic]
+!assert_true(F)
    <- if (F) { !test_passed(assert_true) } else { !test_failed(assert_true, ["Expected '", F, "'"]) }.

@assert_false[atomic]
+!assert_false(F)
    <- if (F) { !test_failed(assert_false, ["Expected 'not ", F, "'"]) } else { !test_passed(assert_false) }.

@assert_contains[atomic]
+!assert_contains(Coll, E)
    <- if (.member(E, Coll)) { !test_passed(assert_contains) }
       else { !test_failed(assert_contains, ["Expected '", E, "' in '", Coll, "'"]) }.

@assert_not_contains[atomic]
+!assert_not_contains(Coll, E)
    <- if (.member(E, Coll)) { !test_failed(assert_not_contains, ["Expected '", E, "' NOT in '", Coll, "'"]) }
       else { !test_passed(assert_not_contains) }.

@assert_greater_than[atomic]
+!assert_greater_than(X, Y)
    <- if (.number(X) & .number(Y) & X > Y) { !test_passed(assert_greater_than) }
       else { !test_failed(assert_greater_than, ["Expected '", X, " > ", Y, "'"]) }.

@assert_greater_than_equals[atomic]
+!assert_greater_than_equals(X, Y)
    <- if (.number(X) & .number(Y) & X >= Y) { !test_passed(assert_greater_than_equals) }
       else { !test_failed(assert_greater_than_equals, ["Expected '", X, " >= ", Y, "'"]) }.

@assert_between[atomic]
+!assert_between(X, Low, High)
    <- if (.number(X) & .number(Low) & .number(High) & X >= Low & X <= High) { !test_passed(assert_between) }
       else { !test_failed(assert_between, ["Expected '", Low, " <= ", X, " <= ", High, "'"]) }.

@force_pass[atomic]
+!force_pass <- !test_passed(force_pass).

@force_failure[atomic]
+!force_failure(Msg)
    <- ?current_test(G, L); !count_test(failed, force_failure);
       .log(severe, "force_failure on event '", G, "' forcedly FAILED! Msg: '", Msg, "'").

// bookkeeping: one test(N, Goal, Verdict, Assertion) belief per assertion checked
+!test_passed(Kind) <- ?current_test(G, _); !count_test(passed, Kind); .log(info, Kind, " on event '", G, "' PASSED").
+!test_failed(Kind, Parts)
    <- ?current_test(G, L); !count_test(failed, Kind); !test_text(Parts, "", Why);
       .log(severe, Kind, " on event '", G, "' starting at line ", L, " FAILED! ", Why).
+!count_test(Verdict, Kind)
    <- ?current_test(G, _); .count(test(_, _, _, _), N); +test(N + 1, G, Verdict, Kind).

// the test under way and the line its plan starts at (its label's code_line, from the intention)
current_test(G, L)
    :- running_test(G) & .intention(_, _, Stack, current) & .member(im(Label, {+!Goal[_|_]}, _, _), Stack)
       & Goal = G & _[code_line(L)] = Label.
current_test(G, 0) :- running_test(G).
current_test(unknown, 0) :- not running_test(_).

+!test_text([], Text, Text).
+!test_text([P|Rest], Text0, Text)
    <- if (.string(P)) { .concat(Text0, P, Text1) } else { .term2string(P, S); .concat(Text0, S, Text1) };
       !test_text(Rest, Text1, Text).
