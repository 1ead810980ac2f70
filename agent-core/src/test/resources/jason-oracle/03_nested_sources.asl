// Told contents keep their sources inside the sender's (Jason's .add_nested_source), and ask
// answers carry the belief's annotations except source(self).
c(5).
!t.
+!t <- .my_name(Me);
       .send(Me, tell, b(1)[source(x), y]); .wait(100);
       ?b(1)[source(S)]; .print(S);
       .findall(B, b(_)[source(B)], L); .print(L);
       .send(Me, askOne, b(_), A1); .print(A1);
       .send(Me, askOne, c(_), A2); .print(A2);
       .send(Me, askAll, c(_), A3); .print(A3);
       .stopMAS.
