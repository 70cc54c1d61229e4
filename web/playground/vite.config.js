// The playground: a static site of three pages (Sandbox, Dungeon Builder, Platformer),
// served by `npm run play` and built into playground/dist by `npm run build:playground`.
// The pages import the package with its explanations from ../playground-pkg (the npm
// package's build plus the `explain` feature; the games from ../games-pkg) and the
// bundled maps from ../../examples, so the server may read the whole repository.
import { defineConfig } from "vite";
import { fileURLToPath } from "node:url";

const here = (path) => fileURLToPath(new URL(path, import.meta.url));

export default defineConfig({
  root: here("."),
  base: "./",
  server: { fs: { allow: [here("../..")] } },
  build: {
    outDir: here("dist"),
    emptyOutDir: true,
    target: "es2022",
    rollupOptions: {
      input: {
        index: here("index.html"),
        sandbox: here("sandbox.html"),
        dungeon: here("dungeon.html"),
        platformer: here("platformer.html"),
      },
    },
  },
});
