package jacabot.arch;

import static com.tngtech.archunit.library.Architectures.layeredArchitecture;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;

import com.tngtech.archunit.core.domain.JavaClass;
import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import com.tngtech.archunit.library.Architectures.LayeredArchitecture;
import java.util.Arrays;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;

/**
 * The one rule behind every module's {@code ArchitectureTest}: the module's packages, listed from
 * the bottom up, may only depend downwards; no package cycle; and the module uses nothing of the
 * modules above it in the thesis' layers (cognitive, executive, functional; Chapter 3 §1.1).
 */
public final class PackageLayers {
    private final String root;
    private final List<String> bottomUp;
    private String[] forbidden = new String[0];

    private PackageLayers(String root, List<String> bottomUp) {
        this.root = root;
        this.bottomUp = bottomUp;
    }

    /** Packages of the module under {@code root}, lowest first, each named relative to it ("" is the root). */
    public static PackageLayers of(String root, String... bottomUp) {
        return new PackageLayers(root, Arrays.asList(bottomUp));
    }

    /**
     * Packages of other modules that no class of this one may use, as ArchUnit identifiers:
     * {@code "jacabot.app.."} is a package and its subpackages, {@code "jacabot.robot"} that package alone.
     */
    public PackageLayers mustNotUse(String... packages) {
        this.forbidden = packages;
        return this;
    }

    /** Checks the module's compiled main classes; fails with ArchUnit's list of offending dependencies. */
    public void check() {
        JavaClasses classes = new ClassFileImporter()
                .withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS)
                // the module's own classes only: the modules it uses come as jars
                .withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_JARS)
                .importPackages(root);
        if (classes.isEmpty()) {
            throw new AssertionError("no class found under " + root + ": is the package name right?");
        }
        slices().matching(root + ".(**)").should().beFreeOfCycles().allowEmptyShould(true).check(classes);
        if (bottomUp.size() > 1) {
            everyPackageListed(classes);
            layers().check(classes);
        }
        if (forbidden.length > 0) {
            noClasses().should().dependOnClassesThat().resideInAnyPackage(forbidden).check(classes);
        }
    }

    /** A package left out of the order is in no layer, so nothing about it would be checked: a new package must be placed. */
    private void everyPackageListed(JavaClasses classes) {
        Set<String> listed = bottomUp.stream().map(this::packageOf).collect(Collectors.toSet());
        Set<String> unlisted = new TreeSet<>();
        for (JavaClass c : classes) {
            if (!listed.contains(c.getPackageName())) {
                unlisted.add(c.getPackageName());
            }
        }
        if (!unlisted.isEmpty()) {
            throw new AssertionError("packages in no place of the module's order, so not checked: " + unlisted
                    + "; add each to PackageLayers.of(...) above the packages it uses");
        }
    }

    private LayeredArchitecture layers() {
        LayeredArchitecture rule = layeredArchitecture().consideringOnlyDependenciesInLayers();
        for (String name : bottomUp) {
            rule = rule.layer(label(name)).definedBy(packageOf(name));
        }
        for (int i = 0; i < bottomUp.size(); i++) {
            String[] below = bottomUp.subList(0, i).stream().map(PackageLayers::label).toArray(String[]::new);
            rule = below.length == 0
                    ? rule.whereLayer(label(bottomUp.get(i))).mayNotAccessAnyLayer()
                    : rule.whereLayer(label(bottomUp.get(i))).mayOnlyAccessLayers(below);
        }
        return rule.withOptionalLayers(true);
    }

    private String packageOf(String name) {
        return name.isEmpty() ? root : root + "." + name;
    }

    private static String label(String name) {
        return name.isEmpty() ? "(root)" : name;
    }
}
