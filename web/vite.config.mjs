// vite for development (`npx vite web`) and bundling (`npm run build:web` → web/dist). Both the dev
// server and `vite preview` must send COOP/COEP, or the threaded wasm build cannot load.
import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vite';

const nodeModules = fileURLToPath(new URL('../node_modules/', import.meta.url));

const isolation = {
  'Cross-Origin-Opener-Policy': 'same-origin',
  'Cross-Origin-Embedder-Policy': 'require-corp',
};

export default defineConfig({
  root: new URL('.', import.meta.url).pathname,
  base: './',
  server: { headers: isolation, fs: { allow: ['..'] } },
  preview: { headers: isolation },
  // The render worker imports three by path (import maps do not reach workers).
  resolve: { alias: [{ find: /^\/node_modules\/(.*)$/, replacement: `${nodeModules}$1` }] },
  worker: { format: 'es' },
  build: { outDir: 'dist', emptyOutDir: true, chunkSizeWarningLimit: 1500, target: 'es2022' },
});
