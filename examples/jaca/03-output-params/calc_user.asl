!compute.
+!compute <- makeArtifact("adder", "demo.Adder", []);
    add(4, 5, S); println("4 + 5 = ", S);
    addAndSubtract(0.5, 1.5, S2, D); println("0.5 + 1.5 = ", S2, ", 0.5 - 1.5 = ", D);
    .stopMAS.
