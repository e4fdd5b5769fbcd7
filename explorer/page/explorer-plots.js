// Where the explorer looks and how it draws (docs/explorer.md): the directions of the plots and
// canvas drawing. Every value drawn comes from the module (scatterlab-api.js); nothing here
// computes a model.
(function () {
  'use strict';

  // ---- Geometry (where to look) ----------------------------------------------------------------

  const radians = (deg) => (deg * Math.PI) / 180;
  function direction(thetaDeg, phiDeg) {
    const t = radians(thetaDeg), p = radians(phiDeg);
    return [Math.sin(t) * Math.cos(p), Math.sin(t) * Math.sin(p), Math.cos(t)];
  }
  // The equal-area disk of a hemisphere: radius^2 = 1 - |cos theta|, so equal areas hold equal
  // solid angles and the density of sample dots follows the pdf.
  function diskDirection(x, y, below) {
    const r2 = x * x + y * y;
    if (r2 > 1) return null;
    const cosTheta = 1 - r2, sinTheta = Math.sqrt(Math.max(0, 1 - cosTheta * cosTheta));
    const r = Math.sqrt(r2);
    const c = r > 0 ? x / r : 1, s = r > 0 ? y / r : 0;
    return [sinTheta * c, sinTheta * s, below ? -cosTheta : cosTheta];
  }
  function diskPoint(w) {
    const r = Math.sqrt(Math.max(0, 1 - Math.abs(w[2])));
    const s = Math.hypot(w[0], w[1]);
    return s > 0 ? [(r * w[0]) / s, (r * w[1]) / s] : [0, 0];
  }
  const mean3 = (v, i) => (v[i] + v[i + 1] + v[i + 2]) / 3;

  // ---- Drawing ---------------------------------------------------------------------------------

  const ChannelColours = ['#d1242f', '#1a7f37', '#0969da'];
  const Viridis = [[68, 1, 84], [59, 82, 139], [33, 145, 140], [94, 201, 98], [253, 231, 37]];
  function colourmap(t) {
    const x = Math.min(Math.max(t, 0), 1) * (Viridis.length - 1);
    const i = Math.min(Math.floor(x), Viridis.length - 2), f = x - i;
    return Viridis[i].map((c, k) => Math.round(c + f * (Viridis[i + 1][k] - c)));
  }
  // value / max on a linear or a 4-decade log scale, in [0, 1].
  function scaled(value, max, log) {
    if (!(max > 0) || !(value > 0)) return 0;
    return log ? Math.max(0, 1 + Math.log10(value / max) / 4) : value / max;
  }
  const format = (x) => (x === 0 ? '0' : Math.abs(x) >= 1e4 || Math.abs(x) < 1e-3 ? x.toExponential(3) : x.toPrecision(4));

  function clear(canvas) {
    const g = canvas.getContext('2d');
    g.setTransform(1, 0, 0, 1, 0, 0);
    g.fillStyle = '#fff';
    g.fillRect(0, 0, canvas.width, canvas.height);
    g.font = '11px "DejaVu Sans", sans-serif';
    return g;
  }

  // Polar plot: wo at signed angle t from the normal in the plane of incidence, radius ~ value.
  function drawLobe(canvas, lobe, thetaI, transmission, withCosine) {
    const g = clear(canvas);
    const cx = canvas.width / 2, cy = transmission ? canvas.height / 2 : canvas.height - 24;
    const radius = Math.min(canvas.width / 2 - 20, (transmission ? canvas.height / 2 : canvas.height - 40) - 8);
    g.strokeStyle = '#d0d7de';
    g.beginPath();
    g.arc(cx, cy, radius, transmission ? 0 : Math.PI, 2 * Math.PI);
    g.moveTo(cx - radius, cy);
    g.lineTo(cx + radius, cy);
    g.moveTo(cx, cy);
    g.lineTo(cx, cy - radius);
    g.stroke();
    const at = (t, r) => [cx + r * Math.sin(radians(t)), cy - r * Math.cos(radians(t))];
    // wi (toward the viewer's left, t = -theta_i) and its mirror direction.
    g.setLineDash([4, 3]);
    g.strokeStyle = '#8c959f';
    for (const t of [-thetaI, thetaI]) {
      g.beginPath();
      g.moveTo(cx, cy);
      g.lineTo(...at(t, radius));
      g.stroke();
    }
    g.setLineDash([]);
    g.fillStyle = '#57606a';
    g.fillText('wi', ...at(-thetaI, radius + 10));
    const n = lobe.t.length;
    let max = 0;
    const value = (i, c) => lobe.f[4 * i + c] * (withCosine ? Math.abs(Math.cos(radians(lobe.t[i]))) : 1);
    for (let i = 0; i < n; ++i) for (let c = 0; c < 3; ++c) max = Math.max(max, value(i, c));
    if (max > 0) {
      for (let c = 0; c < 3; ++c) {
        g.strokeStyle = ChannelColours[c];
        g.lineWidth = 1.5;
        g.beginPath();
        for (let i = 0; i < n; ++i) {
          const [x, y] = at(lobe.t[i], (radius * value(i, c)) / max);
          if (i === 0) g.moveTo(x, y);
          else g.lineTo(x, y);
        }
        g.stroke();
      }
      g.lineWidth = 1;
    }
    g.fillStyle = '#1f2328';
    g.fillText((withCosine ? 'max f·|cos θo| = ' : 'max f = ') + format(max) + ' 1/sr', 8, 14);
    if (max === 0) g.fillText('f = 0 in this plane (a delta lobe has no density: see the samples)', 8, 30);
    return max;
  }

  // One or two equal-area disks (above, and below for transmission) coloured by value(i).
  function drawDisks(canvas, grid, disks, value, max, log, grey) {
    const g = clear(canvas);
    const size = Math.min(canvas.height - 30, canvas.width / disks.length - 20);
    const image = g.createImageData(grid, grid);
    disks.forEach((disk, d) => {
      for (let j = 0; j < grid; ++j)
        for (let i = 0; i < grid; ++i) {
          const k = 4 * (j * grid + i), index = disk.index[j * grid + i];
          if (index < 0) {
            image.data.set([255, 255, 255, 255], k);
            continue;
          }
          const t = scaled(value(index), max, log);
          image.data.set(grey ? [255 - 150 * t, 255 - 150 * t, 255 - 150 * t, 255] : [...colourmap(t), 255], k);
        }
      const offscreen = document.createElement('canvas');
      offscreen.width = offscreen.height = grid;
      offscreen.getContext('2d').putImageData(image, 0, 0);
      const x0 = 10 + d * (size + 20), y0 = 20;
      g.imageSmoothingEnabled = false;
      // Row j of the grid is y = +1 at the top.
      g.drawImage(offscreen, x0, y0, size, size);
      g.strokeStyle = '#8c959f';
      g.beginPath();
      g.arc(x0 + size / 2, y0 + size / 2, size / 2, 0, 2 * Math.PI);
      g.stroke();
      g.fillStyle = '#1f2328';
      g.fillText(disk.below ? 'below (transmission)' : 'above (reflection)', x0, 12);
      disk.frame = { x0, y0, size };
    });
    return g;
  }

  // The directions of a grid x grid raster of the disks, in one array of pairs.
  function diskPairs(grid, wi, transmission) {
    const disks = [{ below: false }].concat(transmission ? [{ below: true }] : []);
    const pairs = [];
    let n = 0;
    for (const disk of disks) {
      disk.index = new Int32Array(grid * grid).fill(-1);
      for (let j = 0; j < grid; ++j)
        for (let i = 0; i < grid; ++i) {
          const x = ((i + 0.5) / grid) * 2 - 1, y = 1 - ((j + 0.5) / grid) * 2;
          const wo = diskDirection(x, y, disk.below);
          if (!wo) continue;
          disk.index[j * grid + i] = n++;
          pairs.push(...wi, ...wo);
        }
    }
    return { disks, pairs: Float64Array.from(pairs), count: n };
  }

  function markDirection(g, disks, w, colour, label) {
    const disk = disks.find((d) => d.below === w[2] < 0);
    if (!disk) return;
    const [x, y] = diskPoint(w);
    const { x0, y0, size } = disk.frame;
    const px = x0 + ((x + 1) / 2) * size, py = y0 + ((1 - y) / 2) * size;
    g.strokeStyle = colour;
    g.beginPath();
    g.arc(px, py, 5, 0, 2 * Math.PI);
    g.stroke();
    g.fillStyle = colour;
    g.fillText(label, px + 7, py - 4);
  }

  function drawAlbedo(canvas, thetas, curve, thetaI) {
    const g = clear(canvas);
    const left = 44, right = canvas.width - 12, top = 12, bottom = canvas.height - 28;
    let max = 1;
    for (let i = 0; i < thetas.length; ++i) for (let c = 0; c < 3; ++c) max = Math.max(max, curve.values[4 * i + c]);
    max = Math.ceil(max * 10) / 10;
    const X = (theta) => left + ((right - left) * theta) / 90, Y = (a) => bottom - ((bottom - top) * a) / max;
    g.strokeStyle = '#d0d7de';
    g.fillStyle = '#57606a';
    for (let a = 0; a <= max + 1e-9; a += max > 2 ? 0.5 : 0.2) {
      g.beginPath();
      g.moveTo(left, Y(a));
      g.lineTo(right, Y(a));
      g.stroke();
      g.fillText(a.toFixed(1), 8, Y(a) + 4);
    }
    for (let t = 0; t <= 90; t += 15) g.fillText(t + '°', X(t) - 8, bottom + 14);
    g.fillText('θi', right - 14, bottom + 26);
    for (let c = 0; c < 3; ++c) {
      g.strokeStyle = ChannelColours[c];
      g.beginPath();
      thetas.forEach((theta, i) => (i ? g.lineTo : g.moveTo).call(g, X(theta), Y(curve.values[4 * i + c])));
      g.stroke();
    }
    g.strokeStyle = '#8c959f';
    g.setLineDash([4, 3]);
    g.beginPath();
    g.moveTo(X(thetaI), top);
    g.lineTo(X(thetaI), bottom);
    g.stroke();
    g.setLineDash([]);
  }

  window.scatterlabPlots = { radians, direction, diskPoint, diskPairs, mean3, format, drawLobe, drawDisks, markDirection,
                             drawAlbedo };
})();
