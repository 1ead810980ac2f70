!open.
+!open <- makeArtifact("stock", "shop.Stock", [2], S); focus(S); !sell_all.
+!sell_all <- sell; !sell_all.
-!sell_all [env_failure_reason(sold_out)] <- println("sold out"); .stopMAS.
+items(N) <- println(N, " left").
