// Issue 24, items 4-5 on the page: the built size as an alternative to the resolution (its estimate
// from the core's real_size formula), the kits picker's line before a run, "Fit my kits" setting
// the form, the result checked against the kits after a run, and bad input said in words.
import fs from 'node:fs';
import path from 'node:path';
import { test, expect } from '@playwright/test';
import { MESHES, OUT } from './support/paths.js';
import { openPage, pickFile, expectNoPageErrors } from './support/page.js';
import { cli } from './support/cli.js';

test('size field, kits picker and Fit my kits on the bunny', async ({ page }) => {
  test.setTimeout(180_000);
  const { errors } = await openPage(page);
  await page.uncheck('#autorun');
  await pickFile(page, 'bunny.obj', fs.readFileSync(path.join(MESHES, 'bunny.obj')));
  await expect(page.locator('#estimate')).toContainText('Resolution chosen for this shape', { timeout: 30_000 });

  // The size replaces the resolution; the estimate follows it.
  await page.check('#size-mode');
  await expect(page.locator('#resolution')).toBeDisabled();
  await page.fill('#size-cm', '50');
  await expect(page.locator('#estimate')).toContainText('At 50 cm', { timeout: 20_000 });
  const balls = async () => Number((await page.locator('#estimate').textContent()).match(/≈ (\d+) balls/)[1]);
  const at50 = await balls();
  // The same formula as the CLI: `run --size-cm 50` starts from a Z0 of as many balls.
  fs.mkdirSync(OUT, { recursive: true });
  const z0 = cli(['run', path.join(MESHES, 'bunny.obj'), '--size-cm', '50', '--initial-only', '-o',
    path.join(OUT, 'size50.zome.json')]);
  expect(Number(z0.match(/\): (\d+) balls,/)[1])).toBe(at50);
  await page.fill('#size-cm', '80');
  await expect(page.locator('#estimate')).toContainText('At 80 cm', { timeout: 20_000 });
  expect(await balls()).toBeGreaterThan(at50);
  expect((await page.evaluate(() => window.zomeify.options())).size_cm).toBe(80);
  for (const bad of ['-5', '100000']) {
    await page.fill('#size-cm', bad);
    await expect(page.locator('#estimate')).toHaveText(/^The size must be a number of centimetres from 25 to 1900\./);
  }
  await page.fill('#size-cm', '50');
  await expect(page.locator('#estimate')).toContainText('At 50 cm', { timeout: 20_000 });

  // One Creator 3: the line before the run says whether the estimate fits.
  await page.click('#kits-picker summary');
  await page.fill('#kit-creator3', '1');
  await expect(page.locator('#kit-fit')).toContainText('With your kits (1 x Creator 3): a model of about', { timeout: 20_000 });
  await page.fill('#kit-basic', '-1');
  await expect(page.locator('#kit-fit')).toHaveText(/^Basic: the number of kits must be a whole number/);
  await page.fill('#kit-basic', '0');

  // Fit my kits: the form takes the core's plan (resolution mode, a target within the kits).
  await page.check('#size-mode');
  await page.uncheck('#size-mode');
  await page.click('#fit-kits');
  await expect(page.locator('#kit-fit')).toContainText('Fit my kits (1 x Creator 3):', { timeout: 30_000 });
  const line = await page.locator('#kit-fit').textContent();
  const [, cells, target] = line.match(/: (\d+) cells, target (\d+) balls/);
  expect(await page.inputValue('#resolution')).toBe(cells);
  expect(await page.inputValue('#target')).toBe(target);
  expect(await page.isChecked('#size-mode')).toBe(false);

  // A short run: afterwards the result is checked against the kits, in words.
  await page.evaluate(() => window.zomeify.run({ seconds: 5 }));
  await expect(page.locator('#kit-missing')).toHaveText(/^Your kits \(1 x Creator 3\) (hold every part of this model\.|do not hold this model: missing .*)/);
  const verdict = await page.locator('#kit-missing').textContent();
  const report = await page.evaluate(() => window.zomeify.parts());
  fs.mkdirSync(OUT, { recursive: true });
  fs.writeFileSync(path.join(OUT, 'fit-kits.txt'), `${line}\n${verdict}\nballs ${report.balls}\n`);
  await expectNoPageErrors(errors);
});
