package c4jason;

/**
 * The environment class of CArtAgO 2's JaCa ({@code environment: c4jason.CartagoEnvironment}),
 * for its older examples. It is {@link jacabot.cartago.bridge.CartagoEnvironment}.
 */
public class CartagoEnvironment extends jacabot.cartago.bridge.CartagoEnvironment {
}
