// Bundles the replay page at build time: src/replay.js with three.js (esbuild, one script)
// into page.html, which keeps one marker, __CBBG_REPLAY_DATA__, for `cbbg replay` to
// fill with a run's trials.
//   node viewer/build.mjs OUT.html
import { build } from "esbuild";
import { readFileSync, renameSync, writeFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";

const here = dirname(fileURLToPath(import.meta.url));
const out = process.argv[2];
if (!out) {
  console.error("build.mjs: usage: node build.mjs OUT.html");
  process.exit(2);
}

const bundle = await build({
  entryPoints: [join(here, "src", "replay.js")],
  bundle: true,
  minify: true,
  format: "iife",
  target: "es2020",
  legalComments: "eof",
  write: false,
  logLevel: "warning",
});
const script = bundle.outputFiles[0].text;
for (const forbidden of ["</script", "__CBBG_REPLAY_DATA__"]) {
  if (script.toLowerCase().includes(forbidden.toLowerCase())) {
    console.error(`build.mjs: the bundle holds '${forbidden}', which would break the page`);
    process.exit(1);
  }
}
const page = readFileSync(join(here, "page.html"), "utf8");
const [before, after, extra] = page.split("__CBBG_REPLAY_SCRIPT__");
if (after === undefined || extra !== undefined) {
  console.error("build.mjs: page.html must hold __CBBG_REPLAY_SCRIPT__ once");
  process.exit(1);
}
writeFileSync(out + ".tmp", before + script + after);
renameSync(out + ".tmp", out);
