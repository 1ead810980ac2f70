// A plan body that starts with `true`: Jason reads the plan without it (`+!g <- true.` is the
// usual empty plan). A later `true`, or one leading the body of a plan term, is an action,
// which fails without an environment.
!start.
+!empty <- true.
+!first <- true; .print(first_ran).
+!second <- true; true; .print(second_ran).
-!second[error(E)] <- .print(second_failed(E)).
@ctx +!ctx : true <- true; .print(ctx_ran).
+!termed[error(E)] <- .print(never).
-!termed[error(E)] <- .print(termed_failed(E)).
+!start <-
    !empty; .print(empty_ran);
    !first; !second; !ctx;
    .relevant_plans({+!empty}, L1); .print(L1);
    .relevant_plans({+!first}, L2); .print(L2);
    .relevant_plans({+!ctx}, L3); .print(L3);
    .add_plan("+!texted <- true; .print(texted_ran).");
    !texted;
    .relevant_plans({+!texted}, L4); .print(L4);
    .add_plan({+!braced <- true; .print(braced_ran)});
    !try_braced;
    .stopMAS.
+!try_braced <- !braced.
-!try_braced[error(E)] <- .print(braced_failed(E)).
