!greet.
+!greet <- println("Hello, world!"); .stopMAS.
