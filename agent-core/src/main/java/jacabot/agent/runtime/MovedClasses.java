package jacabot.agent.runtime;

import java.io.IOException;
import java.io.InputStream;
import java.net.URL;
import java.util.Enumeration;
import java.util.Properties;

/**
 * Classes a project file may still name under an old name: each module lists its own in
 * {@code META-INF/jacabot/moved-classes.properties} (old name = new name), and a "class not found"
 * names the new one.
 */
final class MovedClasses {
    static final String RESOURCE = "META-INF/jacabot/moved-classes.properties";

    private MovedClasses() {
    }

    /** {@return ": it is now N" for a moved class, or ""} */
    static String hint(String className) {
        try {
            Enumeration<URL> lists = MovedClasses.class.getClassLoader().getResources(RESOURCE);
            while (lists.hasMoreElements()) {
                var moved = new Properties();
                try (InputStream in = lists.nextElement().openStream()) {
                    moved.load(in);
                }
                String now = moved.getProperty(className);
                if (now != null) {
                    return ": it is now " + now;
                }
            }
        } catch (IOException e) {
            // no hint then
        }
        return "";
    }
}
