// Issue 24: a shared link gives the sender's Build-view steps. The link renumbers the balls, so
// steps are compared by what a builder sees: the parts each step lists, and the exact positions
// of its balls and struts.
import { test, expect } from '@playwright/test';
import { openPage } from './support/page.js';

/** Every step of the Build view: its parts lines as shown, and its balls and struts by position. */
async function readSteps(page) {
  await page.click('#build-toggle');
  await expect(page.locator('#build-text')).toContainText('Step 1 of');
  return page.evaluate(async () => {
    const plan = await window.zomeify.openBuildView();
    const at = (i) => plan.nodes[i].join(',');
    const out = [];
    for (let k = 0; k < plan.steps.length; k++) {
      await window.zomeify.buildStep(k);
      const s = plan.steps[k];
      out.push({
        text: document.getElementById('build-text').textContent,
        parts: [...document.querySelectorAll('#build-parts li')].map((li) => li.textContent),
        balls: s.balls.map(at).sort(),
        struts: s.struts.map(([a, b]) => [at(a), at(b)].sort().join(' ')).sort(),
      });
    }
    return out;
  });
}

test('the steps of a shared link are the sender\'s', async ({ page, browser }) => {
  test.setTimeout(120_000);
  await openPage(page);
  const url = await page.evaluate(() => window.zomeify.shareLink());
  const sent = await readSteps(page);
  expect(sent.length).toBeGreaterThan(3);

  const fresh = await (await browser.newContext()).newPage();
  const { errors } = await openPage(fresh, url);
  expect((await fresh.evaluate(() => window.zomeify.summary())).source).toBe('link');
  const received = await readSteps(fresh);
  expect(received.length).toBe(sent.length);
  for (let k = 0; k < sent.length; k++) expect(received[k], `step ${k + 1}`).toEqual(sent[k]);
  expect(errors).toEqual([]);
});
