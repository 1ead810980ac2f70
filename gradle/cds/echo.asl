// The other agent of the class-data sharing training run: answers a tell and an achieve.
@ping +ping(N)[source(S)] <- -ping(N)[source(S)].
@answer +!answer[source(S)] <- .send(S, tell, pong(1)).
