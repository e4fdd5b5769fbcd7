// The lab report in a real browser: opens DIR/index.html from the file system in
// Debian's headless Chromium, driven by playwright-core (both installed by scripts/setup), and
// checks that every image loaded, every chart was drawn by Chart.js with data on a canvas that
// is not blank, that every material has its renders or the renderer's message in their place,
// that every material links to the report's explorer, which opens with it selected, and that
// the pages logged no console error and no request failed. Saves a
// full-page screenshot beside the report (DIR/../report-screenshot.png, or SCREENSHOT).
//
// Usage: node browser_test.mjs REPORT_DIR [SCREENSHOT.png] [--expect-failed N] [--expect-unrendered N]
// --expect-failed N: exactly N materials must be marked FAIL (default 0), each with its failing
// rows listed. --expect-unrendered N: exactly N materials have no renders, each showing the
// renderer's message instead (default 0). Exit 0 when every check passes; otherwise prints each failure and exits 1.
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { withChromium, watchForErrors } from './chromium.mjs';

const args = process.argv.slice(2);
const takeCount = (flag) => {
  const at = args.indexOf(flag);
  return at >= 0 ? Number(args.splice(at, 2)[1]) : 0;
};
const expectedFailed = takeCount('--expect-failed');
const expectedUnrendered = takeCount('--expect-unrendered');
const [reportDir, screenshotArg] = args;
if (!reportDir || !Number.isInteger(expectedFailed) || !Number.isInteger(expectedUnrendered)) {
  console.error('usage: node browser_test.mjs REPORT_DIR [SCREENSHOT.png] [--expect-failed N] [--expect-unrendered N]');
  process.exit(2);
}
const index = path.resolve(reportDir, 'index.html');
const screenshot = path.resolve(screenshotArg || path.join(path.dirname(path.resolve(reportDir)), 'report-screenshot.png'));
const failures = [];
const fail = (what) => failures.push(what);

await withChromium(async (context) => {
  const page = await context.newPage();
  watchForErrors(page, fail);

  await page.goto(pathToFileURL(index).href, { waitUntil: 'load' });
  // Closed <details> still load their images; open them so the screenshot shows everything a reader can.
  await page.evaluate(() => document.querySelectorAll('details').forEach((d) => { d.open = true; }));
  await page.waitForFunction(() => Array.from(document.images).every((img) => img.complete), null, { timeout: 30000 });

  const images = await page.evaluate(() => Array.from(document.images).map((img) => ({
    src: img.getAttribute('src'), width: img.naturalWidth, height: img.naturalHeight })));
  if (images.length === 0) fail('the page has no images');
  for (const image of images)
    if (!(image.width > 0 && image.height > 0)) fail('image did not load: ' + image.src);

  const charts = await page.evaluate(() => {
    const specs = JSON.parse(document.getElementById('chart-data').textContent);
    return specs.map((spec) => {
      const chart = window.scatterlabCharts && window.scatterlabCharts[spec.id];
      const canvas = document.getElementById(spec.id);
      if (!chart || !canvas) return { id: spec.id, drawn: false };
      const datasets = chart.data.datasets.filter((d) => d.legend);
      const points = datasets.reduce((n, d) => n + d.data.length, 0);
      // A canvas is blank when every pixel has the same colour.
      const context = canvas.getContext('2d');
      const pixels = context.getImageData(0, 0, canvas.width, canvas.height).data;
      const colours = new Set();
      for (let i = 0; i < pixels.length && colours.size < 3; i += 4 * 97)
        colours.add(pixels[i] + ',' + pixels[i + 1] + ',' + pixels[i + 2] + ',' + pixels[i + 3]);
      return { id: spec.id, drawn: true, type: chart.config.type, datasets: datasets.length, points,
               width: canvas.width, height: canvas.height, colours: colours.size,
               legend: chart.legend ? chart.legend.legendItems.length : 0 };
    });
  });
  if (charts.length === 0) fail('the page has no charts');
  for (const chart of charts) {
    if (!chart.drawn) { fail('chart not drawn: ' + chart.id); continue; }
    if (chart.datasets === 0 || chart.points === 0) fail('chart without data: ' + chart.id);
    if (!(chart.width > 0 && chart.height > 0) || chart.colours < 2) fail('blank canvas: ' + chart.id);
    if (chart.legend === 0) fail('chart without a legend: ' + chart.id);
  }

  const verdicts = await page.evaluate(() => ({
    materials: document.querySelectorAll('article.material').length,
    summaryRows: document.querySelectorAll('table.summary tbody tr').length,
    failedRows: document.querySelectorAll('table.summary tbody tr.failed').length,
    failedArticles: Array.from(document.querySelectorAll('article.material.failed')).map((a) => ({
      id: a.id, listed: a.querySelectorAll('.failures tr.failed').length,
      colour: getComputedStyle(a.querySelector('h2 .badge')).backgroundColor })),
  }));
  if (verdicts.materials === 0 || verdicts.summaryRows !== verdicts.materials)
    fail('summary rows (' + verdicts.summaryRows + ') do not match the materials (' + verdicts.materials + ')');
  if (verdicts.failedRows !== expectedFailed || verdicts.failedArticles.length !== expectedFailed)
    fail('expected ' + expectedFailed + ' failed materials, the page marks ' + verdicts.failedRows + ' in the summary and ' +
         verdicts.failedArticles.length + ' sections');
  for (const failed of verdicts.failedArticles) {
    if (failed.listed === 0) fail('failed material ' + failed.id + ' lists no failing rows');
    if (failed.colour !== 'rgb(207, 34, 46)') fail('failed material ' + failed.id + ' badge is not red: ' + failed.colour);
  }

  // Every material has its renders: pictures, or the renderer's message where it refused one.
  const renders = await page.evaluate(() => Array.from(document.querySelectorAll('article.material')).map((a) => {
    const section = a.querySelector('section.part-renders');
    if (!section) return { id: a.id, section: false };
    const refusals = Array.from(section.querySelectorAll('.render-refused'));
    return { id: a.id, section: true, images: section.querySelectorAll('figure.render img').length,
             refusals: refusals.map((r) => ({ text: (r.querySelector('code') || r).textContent.trim(),
                                               visible: r.getBoundingClientRect().height > 0 })) };
  }));
  for (const r of renders) {
    if (!r.section) { fail('material ' + r.id + ' has no renders section'); continue; }
    if (r.images === 0 && r.refusals.length === 0) fail('material ' + r.id + ' has neither renders nor the renderer\'s message');
    for (const refusal of r.refusals)
      if (!refusal.text || !refusal.visible) fail('material ' + r.id + ': a refused render without a visible message');
  }
  const unrendered = renders.filter((r) => r.section && r.images === 0).length;
  if (unrendered !== expectedUnrendered)
    fail('expected ' + expectedUnrendered + ' materials without renders, the page has ' + unrendered);

  // Every material links to the explorer preloaded with it; open each link and see it selected.
  const links = await page.evaluate(() => Array.from(document.querySelectorAll('article.material')).map((a) => ({
    id: a.id, href: a.querySelector('a.explorer-link') ? a.querySelector('a.explorer-link').href : null })));
  await page.screenshot({ path: screenshot, fullPage: true });
  for (const link of links) {
    if (!link.href) { fail('material ' + link.id + ' has no explorer link'); continue; }
    const explorer = await context.newPage();
    watchForErrors(explorer, fail);
    await explorer.goto(link.href, { waitUntil: 'load' });
    await explorer.evaluate(() => window.scatterlab.ready);
    await explorer.waitForFunction(() => window.scatterlabExplorer.shown.lobe !== null, null, { timeout: 60000 });
    const selected = await explorer.evaluate(() => ({ id: window.scatterlabExplorer.state.entry.id,
                                                      error: document.getElementById('error-box').hidden ? '' :
                                                        document.getElementById('error-box').textContent }));
    if (selected.id !== link.id || selected.error)
      fail('the explorer link of ' + link.id + ' selected ' + selected.id + (selected.error ? ': ' + selected.error : ''));
    await explorer.close();
  }
  console.log(JSON.stringify({ index, screenshot, images: images.length, charts: charts.length, verdicts, renders, explorerLinks: links.length,
                               points: charts.reduce((n, c) => n + (c.points || 0), 0) }));
});
if (failures.length > 0) {
  for (const failure of failures) console.error('FAIL ' + failure);
  process.exit(1);
}
console.log('PASS: every image loaded, every chart drawn with data, no console errors or failed requests');
