// Playwright config of the browser benchmark: the e2e setup (Debian's Chromium, the page's two
// servers), but only tests/bench/browser*.spec.mjs. run.sh runs browser.spec.mjs; browser_paper.spec.mjs
// (the paper's bunny in the page, about 13 minutes) is run by hand.
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { defineConfig } from '@playwright/test';
import e2e from '../../e2e/playwright.config.js';

const e2eDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../e2e');
export default defineConfig({
  ...e2e,
  testDir: '.',
  testMatch: /browser(_paper)?\.spec\.mjs$/,
  timeout: 300_000,
  outputDir: '../../build/bench/browser-results',
  // The servers' commands are relative to e2e/.
  webServer: e2e.webServer.map((s) => ({ ...s, cwd: e2eDir })),
});
