// no applicable plan for a goal whose plans all fail to unify (error no_applicable), failure events
// no plan applies to (Jason's two warnings), and a .fail_goal of the intention's own goal whose
// failure plan does not apply: that intention goes on
!start.
+!start <- !m(1); !n[a]; !!lost; .wait(100); !top; .print(after_top); .stopMAS.
+!m(2) <- .print(never).
+!n[b] <- .print(never).
-!m(_)[error(E)] <- .print(m, " ", E).
-!n[error(E)] <- .print(n, " ", E).
+!lost <- !g; .print(never).
+!g <- .fail.
-!g[foo] <- .print(never).
+!top <- !h; .print(after_h).
+!h <- !k; .print(never).
+!k <- .fail_goal(h); .print(never).
-!h[foo] <- .print(never).
