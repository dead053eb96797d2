// share_link.js (the #m=1.… fragment, copying), file_names.js (the model's name, download names)
// and samples.js (the bundled samples exist and fit the controls).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, readFileSync } from 'node:fs';
import { linkFromHash, urlWithFragment, copyText, resolutionFromLink, fragmentWithResolution } from '../src/share_link.js';
import { modelBaseName, exportFileName, fileNameFromUrl } from '../src/file_names.js';
import { FORMATS } from '../src/downloads.js';
import { SAMPLES, DEFAULT_SAMPLE } from '../src/samples.js';
import { fakeDocument, setGlobal } from './helpers/fake_dom.mjs';

const LINK = 'm=1.A-IBwQQEAAQACAAEGz9SagQ4UWGrAxwtrQMHGGcEDWFkcAQBB2F9'; // the start of a real link (base64url)

test('a fragment is a share link only when it has an m= parameter', () => {
  assert.equal(linkFromHash('#' + LINK), LINK);
  assert.equal(linkFromHash(LINK), LINK);
  assert.equal(linkFromHash('#v=2&' + LINK), 'v=2&' + LINK);
  assert.equal(linkFromHash(''), null);
  assert.equal(linkFromHash('#'), null);
  assert.equal(linkFromHash('#mm=1.AB'), null);
  assert.equal(linkFromHash('#sum=1.AB'), null);
});

test('the page address with a link: fragment replaced, path and query kept, and it reads back', () => {
  const url = urlWithFragment('http://127.0.0.1:8080/app/?debug=1#m=1.old', LINK);
  assert.equal(url, `http://127.0.0.1:8080/app/?debug=1#${LINK}`);
  assert.equal(linkFromHash(new URL(url).hash), LINK);
});

test('copyText: a refused clipboard falls back to a selected hidden field, removed afterwards', async () => {
  const doc = fakeDocument({ copyResult: false });
  const restoreNavigator = setGlobal('navigator', { clipboard: { writeText: async () => { throw new Error('denied'); } } });
  const restoreDocument = setGlobal('document', doc);
  try {
    assert.equal(await copyText('the link'), false); // execCommand's answer is passed on
    assert.deepEqual(doc.commands, [{ command: 'copy', bodyChildren: ['the link'] }]);
    assert.equal(doc.body.children.length, 0);
  } finally {
    restoreNavigator();
    restoreDocument();
  }
});

test('the model\'s name drops the loaded file\'s extension (any case), and is never empty', () => {
  assert.equal(modelBaseName('torus.zome.json'), 'torus');
  assert.equal(modelBaseName('Bunny.STL'), 'Bunny');
  assert.equal(modelBaseName('scan.v2.obj'), 'scan.v2');
  assert.equal(modelBaseName('notes.txt'), 'notes.txt');
  assert.equal(modelBaseName('.obj'), 'model');
});

test('download names: every format from its template; a base with "parts", "model" or "$&" is literal', () => {
  const names = Object.values(FORMATS).flat().map((t) => exportFileName(t, 'torus'));
  assert.deepEqual(names, ['torus.vef', 'torus-no-panels.vef', 'torus.glb', 'torus.obj', 'torus.mtl', 'torus.zome.json',
    'torus-parts.csv']);
  // Before file_names.js, 'model.vef' became 'parts-parts.vef' for a model named "parts".
  assert.equal(exportFileName('model.vef', 'parts'), 'parts.vef');
  assert.equal(exportFileName('parts.csv', 'bodyparts'), 'bodyparts-parts.csv');
  assert.equal(exportFileName('model.obj', 'shared-model'), 'shared-model.obj');
  assert.equal(exportFileName('model.glb', 'a$&b'), 'a$&b.glb');
  // The two VEF buttons save under different names (issue 38).
  assert.equal(new Set(names).size, names.length);
  assert.equal(exportFileName('model-no-panels.vef', 'model'), 'model-no-panels.vef');
});

test('a URL\'s file name: decoded, query dropped, "mesh" for a directory, a bad %-escape kept as is', () => {
  const base = 'http://127.0.0.1:8080/app/';
  assert.equal(fileNameFromUrl('samples/torus.obj?v=2', base), 'torus.obj');
  assert.equal(fileNameFromUrl('/meshes/caf%C3%A9%20table.stl', base), 'café table.stl');
  assert.equal(fileNameFromUrl('http://other/dir/', base), 'mesh');
  assert.equal(fileNameFromUrl('http://other/50%zz.obj', base), '50%zz.obj'); // decodeURIComponent would throw
});

test('samples: unique ids, the default among them, mesh files present, credited, resolution on the slider', () => {
  const html = readFileSync(new URL('../index.html', import.meta.url), 'utf8');
  const [, min, max] = html.match(/id="resolution" type="range" min="(\d+)" max="(\d+)"/).map(Number);
  const credits = readFileSync(new URL('../public/samples/README.md', import.meta.url), 'utf8');
  assert.equal(new Set(SAMPLES.map((s) => s.id)).size, SAMPLES.length);
  assert.ok(SAMPLES.some((s) => s.id === DEFAULT_SAMPLE));
  for (const s of SAMPLES) {
    assert.ok(existsSync(new URL(`../public/samples/${s.mesh}`, import.meta.url)), s.mesh);
    assert.ok(credits.includes('`' + s.mesh + '`'), `${s.mesh} credited in public/samples/README.md`);
    assert.ok(s.resolution >= min && s.resolution <= max, `${s.id} resolution ${s.resolution}`);
    assert.match(s.credit, /CC BY [34]\.0/);
  }
});

test('a link carries the resolution its model was made at (r=, beside m=), which the page reads back', () => {
  assert.equal(fragmentWithResolution('m=2.AbC', 22), 'm=2.AbC&r=22');
  assert.equal(fragmentWithResolution('m=2.AbC', 0), 'm=2.AbC'); // unknown: no r
  assert.equal(resolutionFromLink('http://x/#m=2.AbC&r=22'), 22);
  assert.equal(resolutionFromLink('m=2.AbC&r=8'), 8);
  assert.equal(resolutionFromLink('#r=12&m=2.AbC'), 12);
  assert.equal(resolutionFromLink('m=2.Ar=5'), 0); // inside the model's base64, not a parameter
  assert.equal(resolutionFromLink('m=2.AbC&r=abc'), 0);
  assert.equal(linkFromHash('#m=2.AbC&r=22'), 'm=2.AbC&r=22'); // the core skips the other parameter
});
