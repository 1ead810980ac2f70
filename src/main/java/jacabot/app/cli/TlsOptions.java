package jacabot.app.cli;

import jacabot.robot.link.LinkTls;
import java.io.IOException;
import java.nio.file.Path;
import javax.net.ssl.SSLContext;

/** The launchers' {@code --tls-store FILE --tls-password-file FILE}: a TLS context, or a one-line user error. */
final class TlsOptions {
    private TlsOptions() {
    }

    static SSLContext context(Path store, Path passwordFile) {
        if (passwordFile == null) {
            throw new UserError("--tls-store needs --tls-password-file FILE (the store's password on its first line)");
        }
        try {
            return LinkTls.fromStore(store, passwordFile);
        } catch (IOException e) {
            throw new UserError(e.getMessage() + "; check --tls-store and --tls-password-file");
        }
    }
}
