// Playwright against the real page in Debian's Chromium (/usr/bin/chromium; no browser download).
// Two servers: cross-origin isolated (threaded build) and without COOP/COEP (single-threaded
// fallback). E2E_ROOT=dist serves the vite build instead of the sources.
import { defineConfig } from '@playwright/test';

export const PORT = Number(process.env.E2E_PORT || 8185);
export const PORT_NO_COI = PORT + 1;
const root = process.env.E2E_ROOT ? `ROOT=${process.env.E2E_ROOT} ` : '';

export default defineConfig({
  testDir: '.',
  testMatch: /.*\.spec\.js$/,
  timeout: 120_000,
  expect: { timeout: 15_000 },
  workers: 1,
  retries: 0,
  reporter: [['list']],
  outputDir: '../build/e2e-results',
  use: {
    browserName: 'chromium',
    baseURL: `http://127.0.0.1:${PORT}`,
    viewport: { width: 1280, height: 800 },
    acceptDownloads: true,
    launchOptions: {
      executablePath: '/usr/bin/chromium',
      args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
        '--disable-background-networking', '--disable-component-update', '--disable-sync',
        '--enable-unsafe-swiftshader'],
    },
  },
  webServer: [
    { command: `${root}PORT=${PORT} node ../web/server.mjs`, url: `http://127.0.0.1:${PORT}/`, reuseExistingServer: false },
    { command: `${root}COI=0 PORT=${PORT_NO_COI} node ../web/server.mjs`, url: `http://127.0.0.1:${PORT_NO_COI}/`,
      reuseExistingServer: false },
  ],
});
