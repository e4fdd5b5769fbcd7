// window.scatterlab, the console API of the explorer (docs/explorer.md): scatterlab's model code
// compiled to WebAssembly (explorer/explorer_api.cpp, loaded by assets/scatterlab-wasm.js). The
// registry validates and builds a material; eval, pdf and sample are the model's own, the C++
// the scatterlab executable runs. Nothing here computes a model: this file passes descriptions,
// directions and numbers to the module and back.
(function () {
  'use strict';

  const help = [
    'await scatterlab.ready                        the module is loaded',
    'scatterlab.eval(material, wi, wo)             f = [r, g, b] in 1/sr, no cosine',
    'scatterlab.pdf(material, wi, wo)              density of the sampler per solid angle of wo',
    'scatterlab.evaluate(material, [{wi, wo}...])  what `scatterlab eval --json` prints',
    'scatterlab.sample(material, wi, count, seed)  draws of the model\'s own sampler',
    'scatterlab.models()                           the registry (`scatterlab models --json`)',
    'scatterlab.complete(material)                 the description with every default filled in',
    'scatterlab.loadTable(name, bytes)             a measured table for {"type": "measured", "file": path}',
    'material: JSON text or an object such as {"type": "conductor", "alpha": 0.2};',
    'wi, wo: [x, y, z] unit vectors in the local frame (z = normal), pointing away from the surface.',
  ].join('\n');

  // ---- The module ------------------------------------------------------------------------------

  let wasm = null;

  function requireModule() {
    if (!wasm) throw new Error('scatterlab: the WebAssembly module is still loading; await scatterlab.ready first');
  }
  function withStrings(texts, call) {
    const pointers = texts.map((text) => {
      const size = wasm.lengthBytesUTF8(text) + 1;
      const pointer = wasm._malloc(size);
      wasm.stringToUTF8(text, pointer, size);
      return pointer;
    });
    try {
      return call(...pointers);
    } finally {
      pointers.forEach((pointer) => wasm._free(pointer));
    }
  }
  const jsonOf = (pointer) => JSON.parse(wasm.UTF8ToString(pointer));

  function materialText(material) {
    if (typeof material === 'string') return material;
    if (material !== null && typeof material === 'object') return JSON.stringify(material);
    throw new TypeError('scatterlab: material must be JSON text or an object, such as {"type": "lambertian"}');
  }

  // A scratch array of doubles in the module's memory, grown as needed.
  const scratch = {};
  function doubles(name, count) {
    let block = scratch[name];
    if (!block || block.count < count) {
      if (block) wasm._free(block.pointer);
      block = scratch[name] = { pointer: wasm._malloc(8 * Math.max(count, 1)), count };
    }
    return block.pointer;
  }
  const heap = (pointer, count) => new Float64Array(wasm.HEAPF64.buffer, pointer, count);

  // Built models by description (the completed JSON text), the most recent last. A measured
  // table is read and its samplers built once, not at every call.
  const built = new Map();
  const MaxBuilt = 6;
  function build(material) {
    requireModule();
    const text = materialText(material);
    const known = built.get(text);
    if (known) {
      built.delete(text);
      built.set(text, known);
      return known;
    }
    const result = withStrings([text], (pointer) => jsonOf(wasm._scatterlab_build(pointer)));
    if (result.error) throw new Error('scatterlab: ' + result.error);
    built.set(text, result);
    if (built.size > MaxBuilt) {
      const [oldest, old] = built.entries().next().value;
      built.delete(oldest);
      wasm._scatterlab_release(old.handle);
    }
    return result;
  }

  // f and pdf at n pairs (6 numbers each in `pairs`): 4 numbers per pair (f r, g, b, pdf).
  function evalPairs(model, pairs, n) {
    const input = doubles('pairs', 6 * n), output = doubles('values', 4 * n);
    heap(input, 6 * n).set(pairs.subarray(0, 6 * n));
    if (wasm._scatterlab_eval_pairs(model.handle, input, n, output) !== 0) throw new Error('scatterlab: unknown model');
    return heap(output, 4 * n).slice();
  }
  function drawSamples(model, wi, count, seed) {
    const output = doubles('samples', 8 * count);
    const failed = wasm._scatterlab_sample(model.handle, wi[0], wi[1], wi[2], count, seed, output);
    return { values: heap(output, 8 * count).slice(), failed };
  }
  function albedoCurve(model, thetas, phiDeg, strata, seed) {
    const input = doubles('thetas', thetas.length), output = doubles('albedo', 4 * thetas.length);
    heap(input, thetas.length).set(thetas);
    const invalid = wasm._scatterlab_albedo(model.handle, input, thetas.length, phiDeg, strata, seed, output);
    return { values: heap(output, 4 * thetas.length).slice(), invalid };
  }

  // ---- The console API -------------------------------------------------------------------------

  function evaluate(material, pairs) {
    requireModule();
    const result = withStrings([materialText(material), JSON.stringify(pairs)], (m, p) =>
      jsonOf(wasm._scatterlab_eval_json(m, p)));
    if (result.error) throw new Error('scatterlab: ' + result.error);
    return result;
  }

  const api = {
    help,
    ready: null,
    models() {
      requireModule();
      return jsonOf(wasm._scatterlab_catalog());
    },
    complete(material) {
      return build(material).material;
    },
    evaluate,
    eval(material, wi, wo) {
      return evaluate(material, [{ wi, wo }]).values[0].f;
    },
    pdf(material, wi, wo) {
      return evaluate(material, [{ wi, wo }]).values[0].pdf;
    },
    sample(material, wi, count = 1000, seed = 1) {
      if (!Number.isInteger(count) || count < 1 || count > 1e7)
        throw new RangeError('scatterlab: count must be an integer in [1, 1e7]');
      // wi is checked (and normalised) by the same code as eval's.
      const checked = evaluate(material, [{ wi, wo: [0, 0, 1] }]).values[0].wi;
      const draws = drawSamples(build(material), checked, count, seed);
      const out = [];
      for (let i = 0; i < count; ++i) {
        const v = draws.values.subarray(8 * i, 8 * i + 8);
        out.push(v[3] > 0 ? { wo: [v[0], v[1], v[2]], pdf: v[3], weight: [v[4], v[5], v[6]], delta: v[7] === 1 }
                          : null);
      }
      return out;
    },
    loadTable(name, bytes) {
      requireModule();
      const path = '/tables/' + String(name).replace(/[^A-Za-z0-9._-]/g, '_');
      wasm.FS.mkdirTree('/tables');
      wasm.FS.writeFile(path, bytes instanceof Uint8Array ? bytes : new Uint8Array(bytes));
      return path;
    },
  };
  window.scatterlab = api;
  api.ready = (typeof window.createScatterlabModule === 'function'
    ? window.createScatterlabModule()
    : Promise.reject(new Error('The WebAssembly module (assets/scatterlab-wasm.js) did not load: is it beside index.html?')))
    .then((module) => {
      wasm = module;
      return api;
    });

  // The explorer's own access to the module (explorer.js), not part of the console API.
  window.scatterlabKernels = { build, evalPairs, drawSamples, albedoCurve, fileSystem: () => wasm.FS };

})();
