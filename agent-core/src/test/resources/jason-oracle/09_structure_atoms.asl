// Jason's parser makes an atom written as an operand of a relational expression (Z = a, a = W) a
// structure; atoms anywhere else (arguments, lists, beliefs, goals) are atoms for .structure.
b(atom).
!t.
+!t <- Z = atom;
  if (.structure(Z)) { .print(z, true) } else { .print(z, false) };
  if (.structure(atom)) { .print(direct, true) } else { .print(direct, false) };
  X = f(atom); X = f(Y); if (.structure(Y)) { .print(farg, true) } else { .print(farg, false) };
  ?b(B); if (.structure(B)) { .print(bel, true) } else { .print(bel, false) };
  atom2 = W; if (.structure(W)) { .print(left, true) } else { .print(left, false) };
  L = [atom3]; L = [H|_]; if (.structure(H)) { .print(list, true) } else { .print(list, false) };
  !g(atom4);
  .stopMAS.
+!g(A) <- if (.structure(A)) { .print(goal, true) } else { .print(goal, false) }.
