// .prefix, .suffix and .sublist: the order of their solutions, strings, and their errors
!main.

+!main
   <- for (.prefix(P, [a,b,c])) { .print(prefix, " ", P) };
      for (.suffix(S, [a,b,c])) { .print(suffix, " ", S) };
      for (.sublist(L, [a,b,c,d])) { .print(sublist, " ", L) };
      for (.prefix(P2, "abc")) { .print("string prefix '", P2, "'") };
      for (.suffix(S2, "ab")) { .print("string suffix '", S2, "'") };
      for (.prefix([X|T], [a,b])) { .print(X, " then ", T) };
      for (.sublist([b|T2], [a,b,c,b])) { .print(b, " then ", T2) };
      .findall(Q, .suffix([_,Q], [1,2,3,4]), Qs); .print(Qs);
      if (.prefix([a], [a,b])) { .print("[a] is a prefix") };
      if (.prefix([b], [a,b])) { .print(wrong) } else { .print("[b] is not a prefix") };
      if (.suffix([b], [a,b])) { .print("[b] is a suffix") };
      if (.sublist([a,c], [a,b,c])) { .print(wrong) } else { .print("[a,c] is not contiguous") };
      if (.sublist([b,c], [a,b,c])) { .print("[b,c] is a sublist") };
      if (.prefix("a", "abc")) { .print("a string prefix") };
      if (.prefix("a", [a,b])) { .print(wrong) } else { .print("a string is no prefix of a list") };
      if (.prefix([a], "abc")) { .print(wrong) } else { .print("a list is no prefix of a string") };
      !try(prefix(P3, abc));
      !try(prefix(P4, Free));
      !try(prefix(x, [a]));
      !try(suffix(S3, Free));
      !try(sublist(L2, "abc"));
      !try(sublist(x, [a]));
      .stopMAS.

+!try(prefix(A, B)) <- .prefix(A, B).
+!try(suffix(A, B)) <- .suffix(A, B).
+!try(sublist(A, B)) <- .sublist(A, B).
-!try(G)[error(E), error_msg(M)] <- .print(E, " ", M).
