package jacabot.agent.testing;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import javax.xml.stream.XMLOutputFactory;
import javax.xml.stream.XMLStreamException;
import javax.xml.stream.XMLStreamWriter;

/**
 * Writes a unit's results as a JUnit XML report ({@code TEST-name.xml}, the format CI servers
 * read): one {@code testsuite} per unit, one {@code testcase} per test, with a {@code failure}
 * (a failed assertion) or an {@code error} (a test plan's error, a run that did not end).
 */
public final class JUnitXmlReport {
    private JUnitXmlReport() {
    }

    /** {@return the file written in {@code dir}} */
    public static Path write(Path dir, String suiteName, AslTestRunner.UnitResult result) throws IOException {
        Files.createDirectories(dir);
        Path file = dir.resolve("TEST-" + suiteName.replaceAll("[^A-Za-z0-9_.-]", "_") + ".xml");
        long failures = result.cases().stream().filter(c -> c.status() == AslTestCase.Status.FAILED).count();
        long errors = result.cases().stream().filter(c -> c.status() == AslTestCase.Status.ERROR).count();
        try (OutputStream out = Files.newOutputStream(file)) {
            XMLStreamWriter x = XMLOutputFactory.newFactory().createXMLStreamWriter(out, "UTF-8");
            x.writeStartDocument("UTF-8", "1.0");
            x.writeCharacters("\n");
            x.writeStartElement("testsuite");
            x.writeAttribute("name", suiteName);
            x.writeAttribute("tests", Integer.toString(result.cases().size()));
            x.writeAttribute("failures", Long.toString(failures));
            x.writeAttribute("errors", Long.toString(errors));
            x.writeAttribute("time", String.format(Locale.ROOT, "%.3f", result.millis() / 1000.0));
            int n = 0;
            for (AslTestCase c : result.cases()) {
                n++;
                x.writeCharacters("\n  ");
                x.writeStartElement("testcase");
                x.writeAttribute("classname", suiteName + (c.agent().isEmpty() ? "" : "." + c.agent()));
                x.writeAttribute("name", c.test() + (c.assertion() == null ? "" : " " + c.assertion()) + " #" + n);
                if (c.status() != AslTestCase.Status.PASSED) {
                    x.writeStartElement(c.status() == AslTestCase.Status.FAILED ? "failure" : "error");
                    x.writeAttribute("message", c.message());
                    x.writeEndElement();
                }
                x.writeEndElement();
            }
            x.writeCharacters("\n");
            x.writeEndElement();
            x.writeCharacters("\n");
            x.writeEndDocument();
            x.close();
        } catch (XMLStreamException e) {
            throw new IOException(file + ": " + e.getMessage(), e);
        }
        return file;
    }
}
