// The explorer in a real browser (docs/explorer.md): opens DIR/index.html from the file system in
// headless Chromium and checks that
//  - the page loads with no console error, its module's catalog is `scatterlab models --json`,
//    and every view is drawn;
//  - window.scatterlab.evaluate (and eval, pdf) equals the native `scatterlab eval --json` to
//    1e-12 relative for every registry model at its defaults and with every value of each of its
//    choices, the given measured table included, at fixed direction pairs;
//  - moving the roughness (alpha) slider changes the plotted lobe;
//  - a value out of range is refused by its input with the registry's message, the views
//    unchanged; an unreadable table shows the error box, the views still drawn; bad directions
//    are refused by the console API with the message of `scatterlab eval`;
// and measures how long an update takes for every analytic model. Saves a screenshot.
//
// Usage: node explorer_test.mjs EXPLORER_DIR SCATTERLAB TABLE SCREENSHOT.png
// EXPLORER_DIR was written by `scatterlab explore TABLE ... --out EXPLORER_DIR`, TABLE first.
// Prints a JSON summary; exit 0 when every check passes, otherwise each failure and exit 1.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { withChromium, watchForErrors, canvasIsDrawn } from './chromium.mjs';

const [explorerDir, scatterlab, tableFile, screenshotArg] = process.argv.slice(2);
if (!explorerDir || !scatterlab || !tableFile || !screenshotArg) {
  console.error('usage: node explorer_test.mjs EXPLORER_DIR SCATTERLAB TABLE SCREENSHOT.png');
  process.exit(2);
}
const index = path.resolve(explorerDir, 'index.html');
const screenshot = path.resolve(screenshotArg);
const failures = [];
const fail = (what) => failures.push(what);
const scratch = fs.mkdtempSync(path.join(os.tmpdir(), 'scatterlab-explorer-test-'));

// Same code, double precision: only the last bits of libm functions may differ between the
// native build (glibc) and WebAssembly (musl and the browser's Math), and they stay far below this.
const RelativeTolerance = 1e-12;

// Fixed pairs: normal incidence, glossy and grazing reflection, anisotropic azimuths, and
// transmissions (wo below the surface).
const direction = (thetaDeg, phiDeg) => {
  const t = (thetaDeg * Math.PI) / 180, p = (phiDeg * Math.PI) / 180;
  return [Math.sin(t) * Math.cos(p), Math.sin(t) * Math.sin(p), Math.cos(t)];
};
const Pairs = [[0, 0, 0, 0], [30, 20, 35, 190], [60, 0, 50, 120], [80, 45, 75, 230], [45, 90, 44, 271],
               [89, 10, 20, 200], [40, 0, 150, 180], [20, 30, 170, 10]]
  .map(([ti, pi, to, po]) => ({ wi: direction(ti, pi), wo: direction(to, po) }));
const pairsFile = path.join(scratch, 'pairs.json');
fs.writeFileSync(pairsFile, JSON.stringify(Pairs));

function nativeEval(material) {
  const out = execFileSync(scatterlab, ['eval', material, '--directions', pairsFile, '--json'], { encoding: 'utf8' });
  return JSON.parse(out);
}
const relative = (a, b) => (a === b ? 0 : Math.abs(a - b) / Math.max(Math.abs(a), Math.abs(b)));

// Every registry model at its defaults, and with each value of each of its choices.
function materialsToCompare(catalog) {
  const out = [];
  for (const model of catalog) {
    if (model.type === 'measured') continue;  // compared through the given table below
    out.push({ type: model.type });
    for (const spec of model.parameters)
      if (spec.kind === 'choice')
        for (const choice of spec.choices)
          if (choice !== spec.default) out.push({ type: model.type, [spec.name]: choice });
  }
  return out;
}

const summary = { index, screenshot };
await withChromium(async (context) => {
  const page = await context.newPage();
  watchForErrors(page, fail);
  await page.goto(pathToFileURL(index).href, { waitUntil: 'load' });
  await page.evaluate(() => window.scatterlab.ready);
  await page.waitForFunction(() => window.scatterlabExplorer.shown.lobe !== null, null, { timeout: 60000 });

  // The catalog is the executable's.
  const nativeCatalog = JSON.parse(execFileSync(scatterlab, ['models', '--json'], { encoding: 'utf8' }));
  const pageCatalog = await page.evaluate(() => window.scatterlab.models());
  if (JSON.stringify(pageCatalog) !== JSON.stringify(nativeCatalog))
    fail('the page\'s catalog differs from `scatterlab models --json`');
  for (const id of ['lobe-canvas', 'heatmap-canvas', 'albedo-canvas', 'samples-canvas'])
    if (!(await canvasIsDrawn(page, '#' + id))) fail('blank canvas after loading: ' + id);

  // Native and WebAssembly values, model by model.
  const compared = materialsToCompare(nativeCatalog).map((material) => ({ native: JSON.stringify(material), page: material }));
  const given = await page.evaluate(() => window.scatterlabPreload.materials[0].material);
  compared.push({ native: path.resolve(tableFile), page: given });
  let worst = 0, values = 0, identical = 0;
  for (const { native, page: material } of compared) {
    const expected = nativeEval(native);
    let got;
    try {
      got = await page.evaluate(([m, p]) => window.scatterlab.evaluate(m, p), [material, Pairs]);
    } catch (error) {
      fail('scatterlab.evaluate threw for ' + JSON.stringify(material) + ': ' + error.message);
      continue;
    }
    for (let i = 0; i < Pairs.length; ++i) {
      const e = expected.values[i], g = got.values[i];
      const numbers = [[e.f[0], g.f[0]], [e.f[1], g.f[1]], [e.f[2], g.f[2]], [e.pdf, g.pdf]];
      for (const [a, b] of numbers) {
        const r = relative(a, b);
        values += 1;
        identical += a === b ? 1 : 0;
        worst = Math.max(worst, r);
        if (!(r <= RelativeTolerance))
          fail('wasm differs from native for ' + JSON.stringify(material) + ' at pair ' + i + ': ' + a + ' vs ' + b);
      }
    }
  }
  // eval and pdf are evaluate's first pair.
  const single = await page.evaluate((p) => [window.scatterlab.eval({ type: 'conductor' }, p.wi, p.wo),
                                            window.scatterlab.pdf({ type: 'conductor' }, p.wi, p.wo)], Pairs[1]);
  const reference = nativeEval('{"type": "conductor"}').values[1];
  if (single[0].some((f, c) => relative(f, reference.f[c]) > RelativeTolerance) || relative(single[1], reference.pdf) > RelativeTolerance)
    fail('scatterlab.eval/pdf differ from the native values: ' + JSON.stringify(single));
  summary.equality = { materials: compared.length, pairs: Pairs.length, values, identical, worstRelative: worst };

  // Moving the roughness slider changes the lobe.
  const updates = () => page.evaluate(() => window.scatterlabExplorer.shown.updateMs.length);
  const settle = (before) => page.waitForFunction((n) => window.scatterlabExplorer.shown.updateMs.length > n, before);
  // Selects an entry of the material list and waits for the views to follow.
  const selectWhere = async (predicate, argument) => {
    const count = await updates();
    await page.evaluate(async ([p, a]) => {
      const x = window.scatterlabExplorer;
      await x.selectEntry(x.state.entries.findIndex(new Function('e', 'a', p)));
    }, [predicate, argument]);
    await settle(count);
  };
  const selectModel = (type) => selectWhere(`return e.kind === 'model' && e.type === ${JSON.stringify(type)};`);
  await selectModel('conductor');
  const lobeBefore = await page.evaluate(() => window.scatterlabExplorer.shown.lobe);
  const imageBefore = await page.evaluate(() => document.getElementById('lobe-canvas').toDataURL());
  let before = await updates();
  const slider = page.locator('#parameters input[type=range][data-parameter=alpha]').first();
  if ((await slider.count()) === 0) fail('the conductor has no alpha slider');
  else {
    await slider.fill('800');
    await settle(before);
    const lobeAfter = await page.evaluate(() => window.scatterlabExplorer.shown.lobe);
    const imageAfter = await page.evaluate(() => document.getElementById('lobe-canvas').toDataURL());
    const material = await page.evaluate(() => window.scatterlabExplorer.state.model.material);
    if (JSON.stringify(lobeAfter.f) === JSON.stringify(lobeBefore.f)) fail('moving the alpha slider left the lobe values unchanged');
    if (imageAfter === imageBefore) fail('moving the alpha slider left the lobe plot unchanged');
    summary.slider = { alphaAfter: material.alpha, lobeMaxBefore: lobeBefore.max, lobeMaxAfter: lobeAfter.max };
  }

  // A value out of range: refused by its input with the registry's message; the views keep the
  // last valid material.
  before = await updates();
  const box = page.locator('#parameters input[type=number][data-parameter=alpha]').first();
  await box.fill('2');
  await page.waitForFunction(() => !document.getElementById('error-box').hidden);
  const refused = await page.evaluate(() => {
    const input = document.querySelector('#parameters input[type=number][data-parameter=alpha]');
    return { message: input.validationMessage, valid: input.checkValidity(),
             box: document.getElementById('error-box').textContent, alpha: window.scatterlabExplorer.state.model.material.alpha };
  });
  if (refused.valid || !refused.message.includes('material key "alpha"') || !refused.message.includes('[0.001, 1]'))
    fail('alpha = 2 was not refused by its input with the spec\'s message: ' + JSON.stringify(refused));
  if (!refused.box.includes('[0.001, 1]')) fail('the error box does not show the spec\'s message: ' + refused.box);
  if (refused.alpha === 2) fail('the views took the refused value');
  if ((await updates()) !== before) fail('a refused value updated the views');
  await box.fill('0.3');
  await page.waitForFunction(() => document.getElementById('error-box').hidden);
  summary.refused = refused.message;

  // Bad directions in the console API: the message of `scatterlab eval`.
  const badDirection = await page.evaluate(() => {
    try { window.scatterlab.eval({ type: 'lambertian' }, [0, 0, 2], [0, 0, 1]); return null; } catch (e) { return e.message; }
  });
  if (!badDirection || !badDirection.includes('not a unit vector')) fail('a non-unit wi was not refused: ' + badDirection);

  // An unreadable table: the error box, and the views still drawn.
  await page.setInputFiles('#table-file', { name: 'broken.binary', mimeType: 'application/octet-stream',
                                            buffer: Buffer.from('not a MERL table') });
  await page.waitForFunction(() => document.getElementById('error-box').textContent.includes('broken.binary'));
  const broken = await page.evaluate(() => ({ text: document.getElementById('error-box').textContent,
                                             visible: document.getElementById('error-box').getBoundingClientRect().height > 0 }));
  if (!broken.visible || !broken.text.includes('"file"')) fail('the unreadable table\'s error is not shown: ' + JSON.stringify(broken));
  for (const id of ['lobe-canvas', 'heatmap-canvas', 'albedo-canvas', 'samples-canvas'])
    if (!(await canvasIsDrawn(page, '#' + id))) fail('blank canvas after an unreadable table: ' + id);
  summary.unreadableTable = broken.text;

  // How long an update takes: each analytic model, then five incident angles.
  const times = {};
  for (const model of nativeCatalog.filter((m) => m.type !== 'measured')) {
    await selectModel(model.type);
    const ms = [];
    for (const theta of [10, 30, 50, 70, 85]) {
      before = await updates();
      await page.locator('#theta-i').fill(String(theta));
      await settle(before);
      ms.push(await page.evaluate(() => window.scatterlabExplorer.state.lastUpdateMs));
    }
    ms.sort((a, b) => a - b);
    times[model.type] = { median: ms[2], max: ms[4] };
  }
  const medians = Object.values(times).map((t) => t.median).sort((a, b) => a - b);
  summary.updateMs = { perModel: times, medianOfMedians: medians[Math.floor(medians.length / 2)],
                       slowestMedian: medians[medians.length - 1] };

  // The given table, for the picture.
  await selectWhere("return e.kind === 'given';");
  await page.screenshot({ path: screenshot, fullPage: true });
});
fs.rmSync(scratch, { recursive: true, force: true });
console.log(JSON.stringify(summary, null, 1));
if (failures.length > 0) {
  for (const failure of failures) console.error('FAIL ' + failure);
  process.exit(1);
}
console.log('PASS: loads without errors, wasm equals native, the slider moves the lobe, bad input is shown');
