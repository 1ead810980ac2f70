package jacabot.robot.link;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.KeyStore;
import java.util.Collections;
import java.util.List;
import javax.net.ssl.KeyManagerFactory;
import javax.net.ssl.SSLContext;
import javax.net.ssl.TrustManagerFactory;

/**
 * TLS for the link when the controller runs on another machine, with the JDK's own TLS and a key
 * store made by the JDK's {@code keytool}: the middleware's store holds its key and certificate,
 * the controller's the certificate it trusts. One store file per side (PKCS12 or JKS), its
 * password in a file of its own, so that neither shows on a command line.
 */
public final class LinkTls {
    private LinkTls() {
    }

    /**
     * {@return a TLS context with the key (when the store has one) and the trusted certificates of
     * {@code store}}
     * @throws IOException when the store cannot be read or opened, with the file and the reason
     */
    public static SSLContext fromStore(Path store, char[] password) throws IOException {
        if (!Files.isRegularFile(store)) {
            throw new IOException(store + ": cannot open the key store (no such file)");
        }
        KeyStore ks;
        try {
            ks = KeyStore.getInstance(store.toFile(), password);
        } catch (IOException | GeneralSecurityException | IllegalArgumentException e) {
            throw new IOException(store + ": cannot open the key store (" + reason(e) + ")", e);
        }
        try {
            SSLContext context = SSLContext.getInstance("TLS");
            KeyManagerFactory kmf = KeyManagerFactory.getInstance(KeyManagerFactory.getDefaultAlgorithm());
            kmf.init(ks, password);
            TrustManagerFactory tmf = TrustManagerFactory.getInstance(TrustManagerFactory.getDefaultAlgorithm());
            tmf.init(ks);
            context.init(hasKey(ks) ? kmf.getKeyManagers() : null, tmf.getTrustManagers(), null);
            return context;
        } catch (GeneralSecurityException e) {
            throw new IOException(store + ": cannot use the key store for TLS (" + reason(e) + ")", e);
        }
    }

    /** {@return the first line of {@code file}: a key store's password} */
    public static char[] readPassword(Path file) throws IOException {
        List<String> lines;
        try {
            lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new IOException(file + ": cannot read the password file (" + reason(e) + ")", e);
        }
        return lines.isEmpty() ? new char[0] : lines.get(0).toCharArray();
    }

    /** {@return the context of {@code store} opened with the password in {@code passwordFile}} */
    public static SSLContext fromStore(Path store, Path passwordFile) throws IOException {
        return fromStore(store, readPassword(passwordFile));
    }

    private static boolean hasKey(KeyStore ks) throws GeneralSecurityException {
        for (String alias : Collections.list(ks.aliases())) {
            if (ks.isKeyEntry(alias)) {
                return true;
            }
        }
        return false;
    }

    private static String reason(Exception e) {
        if (e instanceof NoSuchFileException) {
            return "no such file";
        }
        Throwable t = e;
        while (t.getCause() != null && t.getMessage() == null) {
            t = t.getCause();
        }
        String m = t.getMessage();
        if (m != null && m.contains("password")) {
            return "wrong password?";
        }
        return m != null ? m : t.getClass().getSimpleName();
    }
}
