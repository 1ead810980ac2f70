// .puts's interpolation and its second argument, .lower_case/.upper_case and .replace
!main.

+!main
   <- A = abc; S = "str"; N = 3; F = 1.5; L = [1,b,"c"];
      .puts("a=#{A} u=#{Zed} e=#{1+2} s=#{ A } n=#{} x=#{a} i=#{1}");
      .puts("s=#{S} n=#{N} f=#{F} l=#{L} twice=#{S}#{A}");
      .puts("nested #{#{A}} open #{A");
      .puts("unnamed #{_} #{_}"); .copy_term(f(_), Fresh); .print(Fresh);
      .puts("into #{W} #{A}", R);
      .print(R);
      W = 1;
      .print(R);
      .puts("plain", "tail #{A}");
      .puts("plain", 1);
      .puts("plain", f(A));
      .puts("");
      .puts("#{A}", Bound);
      if (Bound == "abc") { .print("a string") };
      !puts_error(123);
      !puts_error(f(x));
      !puts_error(A);
      .lower_case("AbC", L1); .upper_case("AbC", U1); .print(L1, " ", U1);
      .lower_case(abC, L2); if (L2 == "abc") { .print("lower of an atom is a string") };
      .upper_case(f(a, "b"), U2); .print(U2);
      .lower_case(123, L3); .print(L3);
      .upper_case("a", "A"); .print("checked");
      if (.upper_case("a", a)) { .print(wrong) } else { .print("an atom is not the string") };
      if (.upper_case(Free, "FREE")) { .print("a free variable is taken as its name") };
      .replace("banana", "an", "AN", R1); .print(R1);
      .replace("a.b.c", ".", "x", R2); .print(R2);
      .replace("abc", "[a-b]", "x", R3); .print(R3);
      .replace("abc", "(b)", "[$1]", R4); .print(R4);
      .replace("aaa", "a", "b", "bbb"); .print("replaced");
      if (.replace("a", "a", "b", "a")) { .print(wrong) } else { .print("not the same") };
      .stopMAS.

+!puts_error(X) <- .puts(X).
-!puts_error(X)[error(E), error_msg(M)] <- .print(X, ": ", E, " ", M).
