// Internal actions given wrong arguments: the error and its message, as Jason words them
!go.
+!go <-
  !t(.nth(5, [a,b], X1)); !t(.nth(a, [a,b], X2)); !t(.nth(0, a, X3)); !t(.min([], X4));
  !t(.length(a, X5)); !t(.concat(a, [b], X6)); !t(.substring(1, "abc", X7));
  !t(.term2string(X8, Y8)); !t(.term2string(X9, "f(")); !t(.term2string(3, 3)); !t(.term2string(X10, abc(1)));
  !t(.term2string(f(1), "f(1)")); !t(.term2string(f(1), "f( 1 )"));
  !t(.number("abc", X11)); !t(.random(X12, -1)); !t(.delete(5, [a], X13));
  !t(.suspend(1)); !t(.union(a, [b], X14)); !t(.union([a], b, X15)); !t(.union([a], [b], c));
  !t(.length(X16, 2)); !t(.member(a, b)); !t(.sort(a, X17)); !t(.reverse(a, X18)); !t(.reverse([a], b));
  !t(.reverse("ab", [b])); !t(.max(a, X19)); !t(.difference(a, [b], X20)); !t(.intersection([a], [b], c, d));
  !t(.range(X21, a, 3)); !t(.range(X22, 1, b)); !t(.range(X23, 1, 3, c)); !t(.concat(a, b, c, X24));
  !t(.substring(a, b, c, d, e)); !t(.lower_case(1, X25)); !t(.replace(a, b)); !t(.fail_goal(1));
  !t(.succeed_goal(1)); !t(.drop_desire(1)); !t(.resume(1)); !t(.send(a)); !t(.my_name(a, b)); !t(.abolish(1));
  !t(.add_plan(1)); !t(.add_plan(a)); !t(.add_plan(f(x))); !t(.relevant_plans(a, b, c, d)); !t(.date(a));
  !t(.count(1, X26)); !t(.count("s", X27));
  .print(end);
  .stopMAS.
+!t(A) <- A; .print(ok(A)).
-!t(A)[error(E), error_msg(M)] <- .print(E, " | ", M).
