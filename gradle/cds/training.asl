// The run `gradle installDist` records in the class-data sharing archive (lib/jacabot.jsa): a
// little of what AgentSpeak programs commonly do, so that their classes load from the archive.
// Its output goes to build/tmp/cds/training.log.
edge(a, b). edge(b, c). edge(c, d).
path(X, Y) :- edge(X, Y).
path(X, Y) :- edge(X, Z) & path(Z, Y).
count(0).

!start.

@start +!start
    <- .print("training");
       .findall(Y, path(a, Y), L); .length(L, N); .nth(0, L, First);
       .concat(L, [e, f], L2); .member(e, L2); .delete(e, L2, L3);
       .sort([c, a, b], S); .union(S, [d], U); .difference(U, [a], D); .intersection(U, D, I);
       .max(I, Max); .min(I, Min); .reverse(I, R);
       .term2string(T, "p(1, \"s\", [x])"); .term2string(T, Str); .substring("p", Str);
       .concat("a", "b", AB); .length(AB, ABN);
       X = math.sqrt(16) + math.abs(-2) + (7 mod 3) + (7 div 2) + 2 ** 3;
       for (.range(K, 1, 20)) { -+count(K) };
       ?count(C);
       if (C > 10) { +big(C) } elif (C > 5) { +mid(C) } else { +small(C) };
       while (count(W) & W > 0) { -+count(W - 1) };
       .abolish(big(_));
       !!side(3);
       !risky;
       .send(echo, tell, ping(1));
       .send(echo, achieve, answer).

@side +!side(0).
@side_step +!side(N) <- !side(N - 1).

@risky +!risky <- .fail.
@risky_recovered -!risky <- .print("recovered").

@pong +pong(N)[source(echo)] <- .print("pong ", N); .stopMAS.
