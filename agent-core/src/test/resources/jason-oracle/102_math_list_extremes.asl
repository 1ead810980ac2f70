// math.max and math.min of a list: numbers only; Jason's largest starts at Double.MIN_VALUE
!start.
+!start <- X = 5;
   .print(math.max([-1, -2]), " ", math.min([1, 2]), " ", math.max([1 + 1, X]), " ", math.min([a, -3, "s"]));
   .print(math.min([]), " ", math.max([]), " ", math.max([a, 3]), " ", math.max(3, 4), " ", math.min(2, 1));
   .stopMAS.
