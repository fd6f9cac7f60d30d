import java.io.IOException;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import javax.tools.JavaCompiler;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;

/**
 * Compiles several source trees in one JVM (its JIT warmed once, not once per tree), each into
 * its own classes folder, with the options of `javac --release 11 -Xlint:all -Werror -encoding
 * UTF-8`. Arguments: the number of threads, then pairs of source folder and classes folder.
 * Prints per tree "OK folder" or "FAIL folder" and javac's messages, then "END"; exits 1 if any
 * tree failed or drew a message.
 */
public final class BatchJavac {
    private BatchJavac() {
    }

    public static void main(String[] args) throws Exception {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        ExecutorService pool = Executors.newFixedThreadPool(Integer.parseInt(args[0]));
        List<Future<String>> results = new ArrayList<>();
        for (int i = 1; i + 1 < args.length; i += 2) {
            final String src = args[i];
            final String out = args[i + 1];
            results.add(pool.submit(() -> compile(javac, src, out)));
        }
        boolean ok = true;
        for (Future<String> result : results) {
            String report = result.get();
            ok &= report.startsWith("OK ");
            System.out.println(report);
            System.out.println("END");
        }
        pool.shutdown();
        System.exit(ok ? 0 : 1);
    }

    private static String compile(JavaCompiler javac, String src, String out) throws IOException {
        List<String> files;
        try (Stream<Path> walk = Files.walk(Paths.get(src))) {
            files = walk.map(Path::toString).filter(p -> p.endsWith(".java")).sorted().collect(Collectors.toList());
        }
        Files.createDirectories(Paths.get(out));
        StringWriter log = new StringWriter();
        List<String> options = Arrays.asList("--release", "11", "-Xlint:all", "-Werror", "-encoding", "UTF-8", "-d", out);
        try (StandardJavaFileManager fm = javac.getStandardFileManager(null, null, StandardCharsets.UTF_8)) {
            boolean ok = javac.getTask(log, fm, null, options, null, fm.getJavaFileObjectsFromStrings(files)).call();
            String messages = log.toString();
            return (ok && messages.isEmpty() ? "OK " : "FAIL ") + src + (messages.isEmpty() ? "" : "\n" + messages);
        }
    }
}
