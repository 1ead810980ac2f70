// An internal action Jason cannot load: reported at load (a warning, left out of the recorded
// lines), then run as an action for the environment, which fails without one.
!start.
+!start <- .print(a); .foo(1); .print(b).
-!start[error(E), error_msg(M), code(C)] <- .print(failed(E, M, C)); !other.
+!other <- .my.lib(2).
-!other[error(E), code(C)] <- .print(other_failed(E, C)); .stopMAS.
