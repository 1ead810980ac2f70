+ball(N)[source(ping)] <- -ball(N)[source(ping)]; .send(ping, tell, ball(N + 1)).
