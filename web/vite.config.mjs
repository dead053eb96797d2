// vite for development (`npx vite web`) and bundling (`npm run build:web` → web/dist). Both the dev
// server and `vite preview` must send COOP/COEP, or the threaded wasm build cannot load.
import { defineConfig } from 'vite';

const isolation = {
  'Cross-Origin-Opener-Policy': 'same-origin',
  'Cross-Origin-Embedder-Policy': 'require-corp',
};

export default defineConfig({
  root: new URL('.', import.meta.url).pathname,
  base: './',
  server: { headers: isolation, fs: { allow: ['..'] } },
  preview: { headers: isolation },
  worker: { format: 'es' },
  build: { outDir: 'dist', emptyOutDir: true, chunkSizeWarningLimit: 1500, target: 'es2022' },
});
