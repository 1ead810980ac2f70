package jaca;

/**
 * JaCa's environment class under its own name, so that a CArtAgO project's {@code .mas2j} runs
 * unchanged ({@code environment: jaca.CartagoEnvironment}, with its arguments). It is
 * {@link jacabot.cartago.bridge.CartagoEnvironment}.
 */
public class CartagoEnvironment extends jacabot.cartago.bridge.CartagoEnvironment {
}
