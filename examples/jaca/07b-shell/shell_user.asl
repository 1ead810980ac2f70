lines(0).
!test.
+!test <- makeArtifact("shell", "demo.Shell", [], Id);
    firstLine("echo hello from sh", L); println("first line: ", L);
    focus(Id); stream("seq 3"); +streamed; !finish.
@line [atomic]
+line(N, Text) : lines(K) <- println("line ", N, ": ", Text); -+lines(K + 1); !finish.
+!finish : streamed & lines(3) <- println("done"); !failing.
+!finish.
+!failing <- stream("exit 3").
-!failing [env_failure_reason(exit_code(C))] <- println("a failing command: exit code ", C); .stopMAS.
