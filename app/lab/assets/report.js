// scatterlab lab report: draws every chart of the page with Chart.js from the chart specs
// embedded in index.html (<script id="chart-data" type="application/json">, the same specs
// as in each material's data.json). The specs say what to draw (app/lab/chart.h); this file
// only maps them onto Chart.js options. Each chart object is kept in
// window.scatterlabCharts[id] for the browser test.
(function () {
  'use strict';

  const GUIDE = '#b0b0b0';

  function translucent(color, alpha) {
    const hex = color.replace('#', '');
    const r = parseInt(hex.substring(0, 2), 16), g = parseInt(hex.substring(2, 4), 16), b = parseInt(hex.substring(4, 6), 16);
    return 'rgba(' + r + ',' + g + ',' + b + ',' + alpha + ')';
  }

  function points(list) {
    return list.map(function (p) { return { x: p[0], y: p[1] }; });
  }

  // One series becomes one dataset, plus two for its band (lower, then upper filled down to it).
  function datasets(series) {
    const out = [];
    series.forEach(function (s) {
      const style = s.style;
      if (s.band && s.band.lower.length > 0) {
        out.push({ label: '', data: points(s.band.lower), showLine: true, pointRadius: 0, borderWidth: 0,
                   borderColor: 'transparent', fill: false, legend: false });
        out.push({ label: '', data: points(s.band.upper), showLine: true, pointRadius: 0, borderWidth: 0,
                   borderColor: 'transparent', backgroundColor: translucent(s.color, 0.15), fill: '-1', legend: false });
      }
      out.push({
        label: s.label,
        data: points(s.points),
        showLine: style !== 'points',
        borderColor: style === 'guide' ? s.color || GUIDE : s.color,
        backgroundColor: style === 'points' ? translucent(s.color, 0.8) : s.color,
        borderWidth: style === 'guide' ? 1 : 2,
        borderDash: style === 'dashed' ? [6, 4] : [],
        pointRadius: style === 'points' ? 2.5 : 0,
        pointHoverRadius: style === 'points' ? 4 : 3,
        tension: 0,
        fill: false,
        clip: 6,
        legend: style !== 'guide' && s.label !== '',
        order: style === 'guide' ? 10 : 0
      });
    });
    return out;
  }

  // Log axes: labels at 1, 2 and 5 times a power of ten only, in plain or exponent notation.
  function logTick(value) {
    const mantissa = value / Math.pow(10, Math.floor(Math.log10(value) + 1e-9));
    if (![1, 2, 5].includes(Math.round(mantissa * 100) / 100)) return '';
    return value >= 1e-3 && value < 1e5 ? String(Number(value.toPrecision(3))) : value.toExponential(0);
  }

  function axis(title, log, min, max) {
    const a = { type: log ? 'logarithmic' : 'linear', title: { display: true, text: title },
                ticks: { maxRotation: 0, autoSkipPadding: 6 } };
    if (log) a.ticks.callback = logTick;
    if (min !== null && min !== undefined) a.min = min;
    if (max !== null && max !== undefined) a.max = max;
    return a;
  }

  function config(spec) {
    const polar = spec.kind === 'polar';
    const options = {
      animation: false,
      responsive: true,
      maintainAspectRatio: true,
      aspectRatio: polar ? (spec.x_max - spec.x_min) / (spec.y_max - spec.y_min) : 1.6,
      parsing: false,
      normalized: true,
      plugins: {
        title: { display: true, text: spec.title },
        legend: {
          position: 'bottom',
          labels: { boxWidth: 14, filter: function (item, data) { return data.datasets[item.datasetIndex].legend; } }
        },
        tooltip: { filter: function (item) { return item.dataset.legend; } }
      },
      scales: {
        x: axis(spec.x_label, spec.log_x, spec.x_min, spec.x_max),
        y: axis(spec.y_label, spec.log_y, spec.y_min, spec.y_max)
      }
    };
    return { type: 'scatter', data: { datasets: datasets(spec.series) }, options: options };
  }

  window.scatterlabCharts = {};
  const specs = JSON.parse(document.getElementById('chart-data').textContent);
  specs.forEach(function (spec) {
    const canvas = document.getElementById(spec.id);
    if (!canvas) throw new Error('no canvas for chart ' + spec.id);
    window.scatterlabCharts[spec.id] = new Chart(canvas, config(spec));
  });
  document.documentElement.dataset.chartsDrawn = String(specs.length);
})();
