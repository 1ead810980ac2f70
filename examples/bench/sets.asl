// 2 000 turns of list and set work on small lists: .sort, .union, .difference, .intersection,
// .max, .min, .reverse, .member, .delete.
!go.
+!go <- .print(start); !s(0).
+!s(2000) <- .print(end); .stopMAS.
+!s(N) <- L = [9,3,7,1,8,2,6,4,5,0,N]; .sort(L, S); .union(S, [11,12,13], U); .difference(U, [1,2,3], D);
    .intersection(D, [4,5,6,7,N], I); .max(I, M); .min(L, Mi); .reverse(L, R); .member(7, R); .delete(3, L, L2);
    !s(N + 1).
