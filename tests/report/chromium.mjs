// Debian's headless Chromium driven by playwright-core (both installed by scripts/setup), for the
// browser tests of the lab report (browser_test.mjs) and of the explorer (explorer_test.mjs):
// a fresh profile, and every console error, page error, failed request and HTTP error of a
// page collected as a failure.
import { createRequire } from 'node:module';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const require = createRequire(path.join(here, '..', '..', 'package.json'));
const { chromium } = require('playwright-core');

// Runs `body(context)` with a browser context; the profile is removed afterwards.
export async function withChromium(body, viewport = { width: 1280, height: 900 }) {
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'scatterlab-chromium-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: '/usr/bin/chromium',
    headless: true,
    viewport,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
           '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
  try {
    return await body(context);
  } finally {
    await context.close();
    fs.rmSync(profile, { recursive: true, force: true });
  }
}

// Reports every console error, page error, failed request and HTTP error of `page` to `fail`.
export function watchForErrors(page, fail) {
  page.on('console', (message) => { if (message.type() === 'error') fail('console error: ' + message.text()); });
  page.on('pageerror', (error) => fail('page error: ' + error.message));
  page.on('requestfailed', (request) => fail('request failed: ' + request.url() + ' (' + request.failure()?.errorText + ')'));
  page.on('response', (response) => { if (response.status() >= 400) fail('HTTP ' + response.status() + ': ' + response.url()); });
}

// True when the canvas has at least two colours (sampled every 97th pixel): it was drawn on.
export function canvasIsDrawn(page, selector) {
  return page.evaluate((s) => {
    const canvas = document.querySelector(s);
    if (!canvas || !(canvas.width > 0 && canvas.height > 0)) return false;
    const pixels = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
    const colours = new Set();
    for (let i = 0; i < pixels.length && colours.size < 2; i += 4 * 97)
      colours.add(pixels[i] + ',' + pixels[i + 1] + ',' + pixels[i + 2] + ',' + pixels[i + 3]);
    return colours.size >= 2;
  }, selector);
}
