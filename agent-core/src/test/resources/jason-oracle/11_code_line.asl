// Jason's code_line of a plan (in .intention's labels) is its label's line, or else the line where
// its context starts, or else where its body starts, not the line of its trigger.
!s.
+!a <- !p.
+!b
  : true &
    true
  <- !p.
+!c : true

  <- !p.
+!d(X)
   <- !p; // a comment
      .print(X).
@l1
+!e
  <- !p.
@[atomic]
+!f : true
  <- !p.
+!p <- .intention(_,_,[_,im(L,_,_,_)|_],current); .print(L).
+!s <- !a; !b; !c; !d(1); !e; !f; .stopMAS.
