// paramres explorer: the chart, the certified readouts of a click, the pendulum moving.
// Numbers come from the server's /api/ endpoints; what the page computes itself (the motion
// between samples, and everything in a static export) uses window.PARAMRES_GEN, generated from
// the sympy forms (static/generated.js).
(function () {
  'use strict';
  // the generated script loads on its own (async): the chart does not wait for it, the motion does
  let GEN = window.PARAMRES_GEN;
  const genReady = new Promise((resolve) => {
    const done = () => { GEN = window.PARAMRES_GEN; resolve(); };
    if (GEN) done();
    else document.getElementById('gen-script').addEventListener('load', done);
  });
  const STATIC = !!window.PARAMRES_STATIC;

  // ---------------------------------------------------------------- text, English and Russian
  const TEXT = {
    title: ['Regions of parametric excitation', 'Области параметрического возбуждения'],
    subtitle: ['Pendulum with square-wave modulated length: click the chart for certified multipliers, edges and the motion',
      'Маятник с модулированной длиной: щелчок по диаграмме даёт доказанные мультипликаторы, границы и движение'],
    preset: ['Preset', 'Пример'], system: ['System', 'Система'],
    sys_pendulum: ["pendulum (the paper's)", 'маятник (из статьи)'],
    sys_torsion: ['torsion pendulum', 'крутильный маятник'],
    sys_meissner: ['Meissner (stiffness)', 'Мейснер (жёсткость)'],
    duty: ['Duty D', 'Скважность D'],
    Q: ['Quality factor Q (empty: no friction)', 'Добротность Q (пусто: без трения)'],
    damping: ['Friction model', 'Модель трения'],
    damping_exact: ['exact (damped oscillator)', 'точная (затухающий осциллятор)'],
    damping_paper: ['paper (eqs. 28-30)', 'статьи (ф-лы 28-30)'],
    modulation: ['Modulation', 'Модуляция'],
    mod_square: ['square wave (jump)', 'меандр (скачок)'], mod_ramp: ['linear ramps', 'линейные переходы'],
    switch_time: ['Switching time S/T0', 'Время переключения S/T0'],
    max_order: ['Orders 1 to', 'Порядки от 1 до'], digits: ['Digits', 'Цифр'],
    nonlinear: ['nonlinear run (sin φ)', 'нелинейный расчёт (sin φ)'],
    amplitude: ['Start amplitude (rad)', 'Начальная амплитуда (рад)'],
    legend: ['colour: growth per period ln|μ|max (grey: stable); lines: edges of orders 1…N',
      'цвет: рост за период ln|μ|max (серый: устойчиво); линии: границы порядков 1…N'],
    at_point: ['At the point', 'В точке'], growth: ['ln|μ|max', 'ln|μ|max'], bound: ['bound', 'оценка'],
    interval: ['Interval of order', 'Интервал порядка'],
    lower: ['lower T/T0', 'нижняя T/T0'], upper: ['upper T/T0', 'верхняя T/T0'],
    footer: ['paramres · numbers from the engine (ball arithmetic for every printed digit); the page draws with code generated from the sympy forms.',
      'paramres · числа от движка (шаровая арифметика для каждой цифры); страница рисует кодом, порождённым из формул sympy.'],
    unstable: ['unstable: inside an interval, the swing grows', 'неустойчиво: внутри интервала, размах растёт'],
    stable: ['stable: outside the intervals', 'устойчиво: вне интервалов'],
    edge: ['on an edge: stationary', 'на границе: стационарно'],
    none: ['no interval of instability here', 'интервала неустойчивости нет'],
    click: ['Click the chart to examine a point.', 'Щёлкните по диаграмме, чтобы исследовать точку.'],
    computing: ['computing…', 'вычисляю…'],
    drawn: ['chart drawn', 'диаграмма построена'],
    ball: ['ball arithmetic (python-flint)', 'шаровая арифметика (python-flint)'],
    ms: ['ms', 'мс'],
    // the names in the chart's status line (the system and the friction model)
    name_pendulum: ['pendulum', 'маятник'], name_torsion: ['torsion pendulum', 'крутильный маятник'],
    name_meissner: ['Meissner', 'Мейснер'], name_exact: ['exact', 'точная'], name_paper: ['paper', 'статьи'],
    // the label of the engine's notes (the notes themselves are the engine's, in English)
    note: ['note', 'примечание'],
    Q_none: ['none', 'нет'], languages: ['language', 'язык'],
    certified: ['certified: |printed − exact| <', 'доказано: |напечатано − точно| <'],
    scaled: ['angle shown scaled ×', 'угол показан в масштабе ×'],
    static_note: ['Static copy: precomputed charts, motion computed in the page (double precision, not certified).',
      'Статическая копия: готовые диаграммы, движение считается в странице (двойная точность, без доказательства).'],
    ramp_note: ['Ramps: the chart and the motion are the square wave\'s; a click gives the certified values with ramps.',
      'Переходы: диаграмма и движение — для меандра; щелчок даёт доказанные значения с переходами.'],
    periods: ['periods', 'периодов'],
    pending_note: ['computing… shown: the answer for the previous input', 'вычисляю… показан ответ для прежних данных'],
    failed_note: ['the request failed: no values for the current input', 'запрос не выполнен: значений для текущих данных нет'],
    chart_failed: ['not for the current input: the request failed', 'не для текущих данных: запрос не выполнен'],
    phase_plot: ["phase trajectory: φ' against φ", "фазовая траектория: φ' от φ"],
    nonlinear_run: ['nonlinear pendulum (sin φ, DOP853)', 'нелинейный маятник (sin φ, DOP853)'],
    linear_run: ['linear model', 'линейная модель'], peak: ['peak', 'максимум'],
    rotates: ['it went over the top and rotates', 'он перешёл через верх и вращается'],
    bob1: ['● phase 1 (bob down)', '● фаза 1 (груз внизу)'], bob2: ['● phase 2 (bob up)', '● фаза 2 (груз вверху)'],
    eq1: ['● phase 1 (equivalent pendulum, g/ω₁²)', '● фаза 1 (эквивалентный маятник, g/ω₁²)'],
    eq2: ['● phase 2 (equivalent pendulum, g/ω₂²)', '● фаза 2 (эквивалентный маятник, g/ω₂²)'], measured: ['measured growth', 'измеренный рост'],
  };
  let lang = 'en';
  const say = (key) => (TEXT[key] ? TEXT[key][lang === 'ru' ? 1 : 0] : key);
  function applyLanguage() {
    document.documentElement.lang = lang;
    document.querySelectorAll('[data-i18n]').forEach((el) => { el.textContent = say(el.dataset.i18n); });
    $('Q').placeholder = say('Q_none');
    document.querySelector('.lang').setAttribute('aria-label', say('languages'));
    document.querySelectorAll('.lang button').forEach((b) => b.classList.toggle('on', b.dataset.lang === lang));
    fillPresets();
    updateNote();
    ['chart-panel', 'readout', 'motion'].forEach((id) => setState(id, $(id).dataset.state || ''));
    if (lastPoint) showPoint(lastPoint);
    if (!point) $('point').textContent = say('click');
    Object.entries(statusText).forEach(([id, text]) => {
      if (typeof text === 'function') $(id).textContent = text();
    });
    document.querySelectorAll('.notes .label').forEach((el) => { el.textContent = say('note') + ':'; });
  }

  // ---------------------------------------------------------------- state and controls
  const $ = (id) => document.getElementById(id);
  const controls = ['system', 'duty', 'Q', 'damping', 'modulation', 'switch-time', 'max-order', 'digits', 'nonlinear', 'amplitude'];
  let presets = [];
  let chart = null;        // the last chart document
  let chartParams = null;  // its query
  let point = null;        // {T, m} of the last click
  let run = null;          // the trajectory being animated
  let draws = 0;

  function options() {
    const o = { system: $('system').value, duty: $('duty').value.trim() || '1/2', damping: $('damping').value };
    const Q = $('Q').value.trim();
    if (Q) o.Q = Q;
    return o;
  }
  function query(o) {
    return Object.entries(o).map(([k, v]) => encodeURIComponent(k) + '=' + encodeURIComponent(v)).join('&');
  }
  async function getJSON(url) {
    const r = await fetch(url);
    const doc = await r.json();
    if (!r.ok) throw new Error(doc.error || ('HTTP ' + r.status));
    return doc;
  }
  // a status line: a text (an error message of the server, as it is) or a function that writes it
  // in the current language (written again when the language changes)
  const statusText = {};
  function status(id, text, bad) {
    const el = $(id);
    statusText[id] = text;
    el.textContent = typeof text === 'function' ? text() : text;
    el.classList.toggle('error', !!bad);
  }
  // the engine's notes on a result, each under a label in the page's language (hidden if none)
  function showNotes(id, notes) {
    const box = $(id);
    box.replaceChildren();
    (notes || []).forEach((text) => {
      const p = document.createElement('p'), label = document.createElement('span'), body = document.createElement('span');
      label.className = 'label';
      label.textContent = say('note') + ':';
      body.lang = 'en';
      body.textContent = text;
      p.append(label, body);
      box.appendChild(p);
    });
    box.hidden = !box.childElementCount;
  }
  // whether a panel's results answer the current input: '' (they do, or there are none),
  // 'pending' (a new answer is on its way: the old one is greyed and labelled) or 'failed' (the
  // request failed: the old chart is greyed and labelled, old numbers and motion are cleared)
  function setState(id, state) {
    const el = $(id);
    el.dataset.state = state;
    const note = state === 'pending' ? say('pending_note')
      : state === 'failed' ? say(id === 'chart-panel' ? 'chart_failed' : 'failed_note') : '';
    el.querySelector('.stale-note').textContent = note;
  }
  // the results shown are no longer for the input: each panel that shows some waits for its answer
  function outdated() {
    if (chart) setState('chart-panel', 'pending');
    if (lastPoint) setState('readout', 'pending');
    if (run) setState('motion', 'pending');
  }
  // a canvas drawn in CSS pixels: its backing store is its CSS size times devicePixelRatio (crisp,
  // and its lettering as large in CSS pixels as the font says, whatever the width of the screen)
  function fitCanvas(canvas) {
    const W = canvas.clientWidth, H = canvas.clientHeight;
    if (!W || !H) {  // not laid out (hidden): drawn in its own pixels
      const g = canvas.getContext('2d');
      g.setTransform(1, 0, 0, 1, 0, 0);
      return { g, W: canvas.width, H: canvas.height };
    }
    const dpr = window.devicePixelRatio || 1;
    const bw = Math.round(W * dpr), bh = Math.round(H * dpr);
    if (canvas.width !== bw || canvas.height !== bh) { canvas.width = bw; canvas.height = bh; }
    const g = canvas.getContext('2d');
    g.setTransform(bw / W, 0, 0, bh / H, 0, 0);
    return { g, W, H };
  }
  function updateNote() {
    let note = STATIC ? say('static_note') : '';
    if ($('modulation').value === 'ramp') note = say('ramp_note');
    $('mode-note').textContent = note;
    document.querySelectorAll('.ramp-only').forEach((el) => el.classList.toggle('hidden', $('modulation').value !== 'ramp'));
  }

  // ---------------------------------------------------------------- the chart
  const plot = { left: 58, right: 14, top: 14, bottom: 44 };
  const view = { tmin: 0.2, tmax: 3.2, mmin: 0.005, mmax: 0.95 };
  // the colour saturates smoothly: x = 1 - exp(-v / VSCALE)
  const VSCALE = 0.5;
  // stable: light grey (darker with friction); unstable: pale yellow -> orange -> red -> violet
  const STOPS = [[0, [254, 240, 138]], [0.25, [251, 146, 60]], [0.55, [220, 38, 38]], [1, [76, 29, 149]]];
  function colour(v) {
    if (v === null || v === undefined || !isFinite(v)) return [200, 200, 200];
    if (v <= 1e-9) {
      const d = Math.min(1, -v / 2);
      return [236 - 40 * d, 240 - 36 * d, 245 - 26 * d];
    }
    const x = 1 - Math.exp(-v / VSCALE);
    for (let i = 1; i < STOPS.length; i++) {
      if (x <= STOPS[i][0]) {
        const [x0, c0] = STOPS[i - 1], [x1, c1] = STOPS[i];
        const f = (x - x0) / (x1 - x0);
        return c0.map((c, j) => Math.round(c + f * (c1[j] - c)));
      }
    }
    return STOPS[STOPS.length - 1][1];
  }
  function drawColorbar() {
    // the bar runs over x = 1 - exp(-v / VSCALE); a grey stub on the left is v <= 0
    const c = $('colorbar'), { g, W } = fitCanvas(c), stub = 20, bar = 12;
    const at = (v) => stub + (1 - Math.exp(-v / VSCALE)) * (W - stub - 8);
    for (let i = 0; i < W - 8; i++) {
      const v = i < stub ? -0.3 * (1 - i / stub) : -VSCALE * Math.log(1 - (i - stub) / (W - stub - 8));
      const [r, gg, b] = colour(v);
      g.fillStyle = `rgb(${r},${gg},${b})`;
      g.fillRect(i, 0, 1, bar);
    }
    g.fillStyle = '#374151'; g.font = '11px system-ui, sans-serif'; g.textAlign = 'center';
    for (const v of [0, 0.25, 0.5, 1, 2]) {
      const x = at(v);
      g.fillRect(x, bar, 1, 3);
      g.fillText(String(v), Math.min(x, W - 8), bar + 14);
    }
  }
  // the chart's size in CSS pixels (what it is drawn in), set by each drawing
  const size = { W: 760, H: 520 };
  function xy() {
    const w = size.W - plot.left - plot.right, h = size.H - plot.top - plot.bottom;
    return {
      w, h,
      x: (T) => plot.left + (T - view.tmin) / (view.tmax - view.tmin) * w,
      y: (m) => plot.top + (1 - (m - view.mmin) / (view.mmax - view.mmin)) * h,
      T: (px) => view.tmin + (px - plot.left) / w * (view.tmax - view.tmin),
      m: (py) => view.mmin + (1 - (py - plot.top) / h) * (view.mmax - view.mmin),
    };
  }
  function drawChart() {
    const canvas = $('chart'), fit = fitCanvas(canvas);
    const g = fit.g;
    size.W = fit.W; size.H = fit.H;
    const P = xy();
    g.fillStyle = '#fff';
    g.fillRect(0, 0, size.W, size.H);
    if (chart && chart.growth) {
      const nt = chart.T.length, nm = chart.m.length;
      const img = new ImageData(nt, nm);
      for (let j = 0; j < nm; j++) {
        const row = chart.growth[j];
        for (let i = 0; i < nt; i++) {
          const [r, gg, b] = colour(row[i]);
          const k = 4 * ((nm - 1 - j) * nt + i);
          img.data[k] = r; img.data[k + 1] = gg; img.data[k + 2] = b; img.data[k + 3] = 255;
        }
      }
      const off = document.createElement('canvas');
      off.width = nt; off.height = nm;
      off.getContext('2d').putImageData(img, 0, 0);
      g.imageSmoothingEnabled = true;
      g.drawImage(off, P.x(chart.T[0]), P.y(chart.m[nm - 1]), P.x(chart.T[nt - 1]) - P.x(chart.T[0]), P.y(chart.m[0]) - P.y(chart.m[nm - 1]));
    }
    if (chart && chart.lower) drawEdges(g, P);
    drawAxes(g, P);
    if (point) {
      const px = P.x(point.T), py = P.y(point.m);
      g.strokeStyle = '#111827'; g.lineWidth = 2;
      g.beginPath(); g.arc(px, py, 6, 0, 2 * Math.PI); g.stroke();
      g.strokeStyle = '#fff'; g.lineWidth = 1;
      g.beginPath(); g.arc(px, py, 8, 0, 2 * Math.PI); g.stroke();
    }
    draws += 1;
    canvas.dataset.draws = String(draws);
    $('chart-status').dataset.draws = String(draws);
  }
  function drawEdges(g, P) {
    g.save();
    g.beginPath();
    g.rect(plot.left, plot.top, P.w, P.h);
    g.clip();
    g.strokeStyle = '#0f172a';
    g.lineWidth = 1.4;
    chart.orders.forEach((n, i) => {
      for (const side of [chart.lower[i], chart.upper[i]]) {
        g.beginPath();
        let pen = false;
        side.forEach((T, j) => {
          if (T === null) { pen = false; return; }
          const X = P.x(T), Y = P.y(chart.m[j]);
          if (pen) g.lineTo(X, Y); else g.moveTo(X, Y);
          pen = true;
        });
        g.stroke();
      }
    });
    g.restore();
    // the order written where its interval begins (its lowest depth on the chart)
    g.font = 'bold 12px system-ui, sans-serif';
    g.textAlign = 'center';
    chart.orders.forEach((n, i) => {
      const j = chart.m.findIndex((_, k) => chart.lower[i][k] !== null && chart.upper[i][k] !== null);
      if (j < 0) return;
      const X = P.x((chart.lower[i][j] + chart.upper[i][j]) / 2);
      if (X < plot.left + 6 || X > plot.left + P.w - 6) return;
      const Y = Math.max(plot.top + 12, P.y(chart.m[j]) - 6);
      g.fillStyle = 'rgba(255,255,255,0.85)';
      g.fillRect(X - 7, Y - 11, 14, 14);
      g.fillStyle = '#0f172a';
      g.fillText(String(n), X, Y);
    });
  }
  function drawAxes(g, P) {
    g.strokeStyle = '#374151'; g.lineWidth = 1;
    g.strokeRect(plot.left, plot.top, P.w, P.h);
    g.fillStyle = '#374151';
    g.font = '12px system-ui, sans-serif';
    g.textAlign = 'center';
    for (let T = Math.ceil(view.tmin * 2) / 2; T <= view.tmax + 1e-9; T += 0.5) {
      const X = P.x(T);
      g.beginPath(); g.moveTo(X, plot.top + P.h); g.lineTo(X, plot.top + P.h + 5); g.stroke();
      g.fillText(T.toFixed(1), X, plot.top + P.h + 18);
    }
    g.fillText('T / T₀', plot.left + P.w / 2, size.H - 8);
    g.textAlign = 'right';
    for (let m = 0.1; m <= view.mmax + 1e-9; m += 0.1) {
      const Y = P.y(m);
      g.beginPath(); g.moveTo(plot.left - 5, Y); g.lineTo(plot.left, Y); g.stroke();
      g.fillText(m.toFixed(1), plot.left - 8, Y + 4);
    }
    g.save();
    g.translate(16, plot.top + P.h / 2);
    g.rotate(-Math.PI / 2);
    g.textAlign = 'center';
    g.fillText(lang === 'ru' ? 'глубина модуляции m' : 'modulation depth m', 0, 0);
    g.restore();
  }

  let chartToken = 0;
  async function loadChart() {
    const token = ++chartToken;
    const o = options();
    const params = { ...o, max_order: $('max-order').value, nt: 240, nm: 160 };
    chartParams = params;
    status('chart-status', () => say('computing'));
    if (chart) setState('chart-panel', 'pending');
    try {
      if (STATIC) {
        const id = $('preset').value || presets[0].id;
        chart = await getJSON('data/' + encodeURIComponent(id) + '.json');
        if (token !== chartToken) return;
        setState('chart-panel', '');
        drawChart();
      } else {
        // the colour map first (fast), then the edges over it
        const growth = await getJSON('api/chart?' + query({ ...params, parts: 'growth' }));
        if (token !== chartToken) return;
        chart = growth;
        setState('chart-panel', '');  // what is drawn now is the current input's
        drawChart();
        const edges = await getJSON('api/chart?' + query({ ...params, parts: 'edges' }));
        if (token !== chartToken) return;
        chart = { ...growth, orders: edges.orders, lower: edges.lower, upper: edges.upper };
        drawChart();
      }
      const shown = chart;
      const named = (x) => (TEXT['name_' + x] ? say('name_' + x) : (x || ''));
      status('chart-status', () => say('drawn') + ' · ' + named(shown.system)
        + (shown.Q ? ', Q = ' + shown.Q + ' (' + named(shown.damping) + ')' : ''));
    } catch (e) {
      if (token !== chartToken) return;
      status('chart-status', e.message, true);
      // a chart still drawn is the previous input's (a failed colour map); the edges of the current
      // one may fail alone, and then what is drawn is the current input's
      if ($('chart-panel').dataset.state === 'pending') setState('chart-panel', 'failed');
    }
  }

  // ---------------------------------------------------------------- a click
  function decimal(x, digits) {
    return Number(x.toFixed(digits)).toString();
  }
  let pointToken = 0;
  async function examine(T, m, order) {
    const token = ++pointToken;  // a later click wins: an earlier answer arriving late is dropped
    point = { T: Number(T), m: eval_fraction(m) };
    drawChart();
    $('point').textContent = `T/T0 = ${T},  m = ${m}`;
    $('point').dataset.t = T;
    $('point').dataset.m = m;
    status('point-status', () => say('computing'));
    setState('readout', lastPoint ? 'pending' : '');
    const o = options();
    const q = { ...o, T, m };
    if ($('modulation').value === 'ramp') { q.modulation = 'ramp'; q.switch_time = $('switch-time').value.trim(); }
    if (order) q.order = order;
    if (STATIC) return examineStatic(T, m);
    const started = performance.now();
    const sim = loadRun({ ...o, T, m, ...(order ? { order } : {}) });
    try {
      const doc = await getJSON('api/point?' + query({ ...q, digits: $('digits').value.trim() }));
      if (token !== pointToken) return;
      setState('readout', '');
      showPoint(doc);
      const took = Math.round(performance.now() - started);
      status('point-status', () => `${took} ${say('ms')}` + (doc.multipliers.certified ? ' · ' + say('ball') : ''));
    } catch (e) {
      if (token === pointToken) {
        status('point-status', e.message, true);
        clearPoint();
      }
    }
    await sim;
  }
  function eval_fraction(text) {
    const s = String(text);
    if (s.includes('/')) { const [a, b] = s.split('/'); return Number(a) / Number(b); }
    return Number(s);
  }
  let lastPoint = null;
  // the request for the point failed: no number of an earlier point stays
  function clearPoint() {
    lastPoint = null;
    ['mu1', 'mu2', 'mu-max', 'growth', 'mu-bound', 'order', 'edge-lower', 'edge-upper', 'edge-bound']
      .forEach((id) => { $(id).textContent = '—'; });
    showNotes('mu-notes', []);
    showNotes('edge-notes', []);
    $('verdict').className = 'verdict';
    $('verdict').textContent = '';
    setState('readout', 'failed');
  }
  function showPoint(doc) {
    lastPoint = doc;
    const mu = doc.multipliers, b = doc.boundary;
    const z = (x) => (x.im === '0' ? x.re : `${x.re} ${x.im.startsWith('-') ? '−' : '+'} ${x.im.replace('-', '')} i`);
    $('mu1').textContent = z(mu.multipliers[0]);
    $('mu2').textContent = z(mu.multipliers[1]);
    $('mu-max').textContent = mu.max_modulus;
    $('growth').textContent = mu.growth_rate;
    // one bound for the four numbers above it: the largest of their own bounds
    const bounds = [mu.max_modulus_error_bound, mu.growth_rate_error_bound]
      .concat(mu.multipliers.map((x) => x.error_bound))
      .filter((x) => x !== null && x !== undefined);
    const worst = bounds.reduce((a, x) => (Number(x) > Number(a) ? x : a), bounds[0]);
    $('mu-bound').textContent = say('certified') + ' ' + worst;
    const v = $('verdict');
    v.className = 'verdict ' + (mu.unstable === true ? 'unstable' : mu.unstable === false ? 'stable' : '');
    v.textContent = mu.unstable === true ? say('unstable') : mu.unstable === false ? say('stable') : say('edge');
    showNotes('mu-notes', mu.notes);
    showNotes('edge-notes', b.notes);
    $('order').textContent = String(doc.order);
    if (b.exists) {
      $('edge-lower').textContent = b.lower;
      $('edge-upper').textContent = b.upper;
      $('edge-bound').textContent = say('certified') + ' ' + b.error_bound;
    } else {
      $('edge-lower').textContent = $('edge-upper').textContent = '—';
      $('edge-bound').textContent = say('none');
    }
  }

  // ---------------------------------------------------------------- the motion
  let runToken = 0;
  async function loadRun(q) {
    const token = ++runToken;
    // as many periods as show the growth (or decay) without swamping the start
    const v = growthAt(Number(q.T), eval_fraction(q.m));
    const periods = v !== null && Math.abs(v) > 0.05 ? Math.max(3, Math.min(12, Math.ceil(2.5 / Math.abs(v)))) : 8;
    const params = { ...q, periods, samples: 48, amplitude: $('amplitude').value.trim() || '0.1' };
    if ($('nonlinear').checked) { params.nonlinear = 1; params.periods = 24; }
    setState('motion', run ? 'pending' : '');
    status('motion-status', () => say('computing'));
    try {
      const doc = await getJSON('api/simulate?' + query(params));
      await genReady;
      if (token !== runToken) return;
      startRun(doc);
    } catch (e) {
      if (token === runToken) {
        status('motion-status', e.message, true);
        stopRun();
      }
    }
  }
  // the request for the run failed: the motion of an earlier input stops and goes
  function stopRun() {
    run = null;
    ['pendulum', 'plot-phi', 'plot-dphi', 'plot-phase'].forEach((id) => {
      const c = $(id);
      c.getContext('2d').clearRect(0, 0, c.width, c.height);
    });
    showNotes('motion-notes', []);
    setState('motion', 'failed');
  }
  function growthAt(T, m) {
    if (!chart || !chart.growth) return null;
    const near = (xs, x) => xs.reduce((best, y, k) => (Math.abs(y - x) < Math.abs(xs[best] - x) ? k : best), 0);
    return chart.growth[near(chart.m, m)][near(chart.T, T)];
  }
  // the parameters of the generated propagator for each phase
  function phases(doc) {
    const g = doc.Q_value === null ? 0 : GEN.gammaOfQ(doc.Q_value);
    return [0, 1].map((h) => {
      const w = GEN.omega0 * Math.sqrt(doc.omega_sq[h]);
      const regime = doc.regimes[h];
      const key = doc.model === 'none' ? 'none/under' : doc.model === 'paper' ? 'paper/under' : 'exact/' + regime;
      const W = key === 'exact/under' ? GEN.Omega(w, g) : 0;
      const L = key === 'exact/over' ? GEN.Lambda(w, g) : 0;
      return { U: GEN.propagator[key], w, g, W, L };
    });
  }
  function stateAt(t) {
    // the state at time t: the generated free-oscillation map from the start of the phase that
    // holds t (linear model); linear interpolation of the samples for a nonlinear run
    if (!run) return null;
    const segs = run.doc.segments;
    let i = segs.findIndex((s) => t <= s.t[s.t.length - 1]);
    if (i < 0) i = segs.length - 1;
    const s = segs[i];
    if (run.doc.nonlinear) {
      let k = 1;
      while (k < s.t.length - 1 && s.t[k] < t) k++;
      const f = (t - s.t[k - 1]) / (s.t[k] - s.t[k - 1] || 1);
      return [s.phi[k - 1] + f * (s.phi[k] - s.phi[k - 1]), s.dphi[k - 1] + f * (s.dphi[k] - s.dphi[k - 1]), s.half];
    }
    const p = run.phases[s.half - 1];
    const u = p.U(t - s.t[0], p.w, p.g, p.W, p.L);
    const x = s.phi[0], v = s.dphi[0];
    return [u[0] * x + u[1] * v, u[2] * x + u[3] * v, s.half];
  }
  function startRun(doc) {
    let amax = 0, vmax = 0;
    doc.segments.forEach((s) => {
      s.phi.forEach((x) => { if (x !== null) amax = Math.max(amax, Math.abs(x)); });
      s.dphi.forEach((x) => { if (x !== null) vmax = Math.max(vmax, Math.abs(x)); });
    });
    const tEnd = doc.segments[doc.segments.length - 1].t.slice(-1)[0];
    run = { doc, phases: phases(doc), amax: amax || 1, vmax: vmax || 1, tEnd, t0: performance.now() };
    setState('motion', '');
    showNotes('motion-notes', doc.notes);
    const scale = run.amax;
    status('motion-status', () => motionStatus(doc, scale));
  }
  function motionStatus(doc, amax) {
    const grow = doc.growth_per_period;
    const what = doc.nonlinear
      ? `${say('nonlinear_run')} · ${say('peak')} |φ| = ${doc.peak_amplitude.toPrecision(4)} rad` + (doc.rotates ? ` · ${say('rotates')}` : '')
      : `${say('measured')} |μ| = ${grow === null ? '—' : grow.toPrecision(8)} · ${say('linear_run')}`;
    return `${doc.periods} ${say('periods')} · ${what}`
      + (doc.nonlinear ? '' : ` · ${say('scaled')}${(0.8 / amax).toPrecision(2)}`);
  }
  function drawTrace(canvas, which, t) {
    const { g, W, H } = fitCanvas(canvas);
    g.clearRect(0, 0, W, H);
    const pad = 6, label = which === 'phi' ? 'φ(t)' : "φ'(t)";
    const lim = which === 'phi' ? run.amax : run.vmax;
    const X = (tt) => 30 + (tt / run.tEnd) * (W - 36);
    const Y = (v) => H / 2 - (v / lim) * (H / 2 - pad);
    g.strokeStyle = '#e5e7eb'; g.beginPath(); g.moveTo(30, H / 2); g.lineTo(W - 4, H / 2); g.stroke();
    // switches
    g.strokeStyle = '#f3f4f6';
    run.doc.segments.forEach((s) => { g.beginPath(); g.moveTo(X(s.t[0]), 0); g.lineTo(X(s.t[0]), H); g.stroke(); });
    for (const [style, upto] of [['#cbd5e1', Infinity], ['#2563eb', t]]) {
      g.strokeStyle = style; g.lineWidth = style === '#2563eb' ? 1.6 : 1;
      g.beginPath();
      let first = true;
      run.doc.segments.forEach((s) => {
        s.t.forEach((tt, k) => {
          if (tt > upto) return;
          const v = s[which][k];
          if (v === null) return;
          if (first) { g.moveTo(X(tt), Y(v)); first = false; } else g.lineTo(X(tt), Y(v));
        });
      });
      g.stroke();
    }
    g.fillStyle = '#374151'; g.font = '12px system-ui, sans-serif'; g.textAlign = 'left';
    g.fillText(label, 2, 14);
  }
  function drawPhase(canvas, t) {
    const { g, W, H } = fitCanvas(canvas);
    g.clearRect(0, 0, W, H);
    const X = (v) => W / 2 + (v / run.amax) * (W / 2 - 10);
    const Y = (v) => H / 2 - (v / run.vmax) * (H / 2 - 10);
    g.strokeStyle = '#e5e7eb';
    g.beginPath(); g.moveTo(0, H / 2); g.lineTo(W, H / 2); g.moveTo(W / 2, 0); g.lineTo(W / 2, H); g.stroke();
    g.strokeStyle = '#7c3aed'; g.lineWidth = 1.3;
    g.beginPath();
    let first = true;
    run.doc.segments.forEach((s) => s.t.forEach((tt, k) => {
      if (tt > t || s.phi[k] === null || s.dphi[k] === null) return;
      if (first) { g.moveTo(X(s.phi[k]), Y(s.dphi[k])); first = false; } else g.lineTo(X(s.phi[k]), Y(s.dphi[k]));
    }));
    g.stroke();
    const st = stateAt(t);
    if (st) { g.fillStyle = '#7c3aed'; g.beginPath(); g.arc(X(st[0]), Y(st[1]), 4, 0, 2 * Math.PI); g.fill(); }
    g.fillStyle = '#374151'; g.font = '12px system-ui, sans-serif';
    g.fillText(say('phase_plot'), 6, 14);
  }
  function drawPendulum(canvas, t) {
    const { g, W, H } = fitCanvas(canvas);
    g.clearRect(0, 0, W, H);
    const st = stateAt(t);
    if (!st) return;
    const [phi, , half] = st;
    // the effective length l = g/omega^2 in units of l0 (the pendulum's l0 (1 -+ m))
    const len = run.doc.omega_sq.map((w2) => 1 / w2);
    const lmax = Math.max(len[0], len[1]);
    const scale = (H - 80) / lmax;
    // the linear model scales: its swing is shown scaled to a largest angle of 0.8 rad
    const shown = run.doc.nonlinear ? phi : 0.8 * phi / run.amax;
    const px = W / 2, py = 44;
    g.fillStyle = '#9ca3af'; g.fillRect(px - 40, py - 6, 80, 6);
    const rod = lmax * scale, l = len[half - 1] * scale;
    const sx = Math.sin(shown), cy = Math.cos(shown);
    g.strokeStyle = '#374151'; g.lineWidth = 3;
    g.beginPath(); g.moveTo(px, py); g.lineTo(px + rod * sx, py + rod * cy); g.stroke();
    // the two positions of the bob on the rod
    g.fillStyle = '#d1d5db';
    len.forEach((L) => { g.beginPath(); g.arc(px + L * scale * sx, py + L * scale * cy, 3, 0, 2 * Math.PI); g.fill(); });
    g.fillStyle = half === 1 ? '#dc2626' : '#2563eb';
    g.beginPath(); g.arc(px + l * sx, py + l * cy, 13, 0, 2 * Math.PI); g.fill();
    g.fillStyle = '#374151'; g.font = '12px system-ui, sans-serif'; g.textAlign = 'left';
    g.fillText(`t/T0 = ${t.toFixed(2)}`, 6, H - 8);
    const bob = chart && chart.system && chart.system !== 'pendulum' ? 'eq' : 'bob';
    g.fillStyle = '#dc2626'; g.fillText(say(bob + '1'), 6, 14);
    g.fillStyle = '#2563eb'; g.fillText(say(bob + '2'), 6, 30);
  }
  let frame = 0;
  function animate(now) {
    if (run) {
      const T0ms = 1400; // one T0 of motion takes 1.4 s on the screen
      const t = (((now - run.t0) / T0ms) % run.tEnd + run.tEnd) % run.tEnd;
      drawPendulum($('pendulum'), t);
      drawTrace($('plot-phi'), 'phi', t);
      drawTrace($('plot-dphi'), 'dphi', t);
      drawPhase($('plot-phase'), t);
      frame += 1;
      $('pendulum').dataset.frame = String(frame);
      $('pendulum').dataset.t = t.toFixed(4);
    }
    requestAnimationFrame(animate);
  }

  // ---------------------------------------------------------------- static copy: all in the page
  function clientRun(T, m, sys, dutyText) {
    // the linear model, piecewise: the generated free-oscillation map and the jump rule
    const law = GEN.laws[sys];
    const D = eval_fraction(dutyText || '1/2');
    const doc = { nonlinear: false, model: 'none', Q_value: null, regimes: ['under', 'under'],
      omega_sq: [law.omega1_sq(m), law.omega2_sq(m)], jump: law.jump(m), periods: 8, segments: [] };
    const ph = phases(doc);
    const lengths = [D * T, (1 - D) * T];
    let s = [Number($('amplitude').value) || 0.1, 0];
    const N = 48;
    let t0 = 0;
    const M = [[1, 0], [0, 1]];
    for (let k = 0; k < doc.periods; k++) {
      for (const h of [0, 1]) {
        const p = ph[h], seg = { half: h + 1, t: [], phi: [], dphi: [] };
        for (let i = 0; i < N; i++) {
          const tt = lengths[h] * i / (N - 1), u = p.U(tt, p.w, p.g, p.W, p.L);
          seg.t.push(t0 + tt); seg.phi.push(u[0] * s[0] + u[1] * s[1]); seg.dphi.push(u[2] * s[0] + u[3] * s[1]);
        }
        doc.segments.push(seg);
        const u = p.U(lengths[h], p.w, p.g, p.W, p.L);
        const kf = h === 0 ? doc.jump : 1 / doc.jump;
        s = [u[0] * s[0] + u[1] * s[1], (u[2] * s[0] + u[3] * s[1]) * kf];
        if (k === 0) { // the monodromy, column by column
          for (let c = 0; c < 2; c++) {
            const a = u[0] * M[0][c] + u[1] * M[1][c], b = (u[2] * M[0][c] + u[3] * M[1][c]) * kf;
            M[0][c] = a; M[1][c] = b;
          }
        }
        t0 += lengths[h];
      }
    }
    const tr = M[0][0] + M[1][1], det = M[0][0] * M[1][1] - M[0][1] * M[1][0];
    const disc = tr * tr / 4 - det;
    const mu = disc >= 0 ? Math.max(Math.abs(tr / 2 + Math.sqrt(disc)), Math.abs(tr / 2 - Math.sqrt(disc))) : Math.sqrt(det);
    doc.growth_per_period = mu;
    return doc;
  }
  async function examineStatic(T, m) {
    await genReady;
    const doc = clientRun(Number(T), eval_fraction(m), chart.system, chart.duty);
    startRun(doc);
    $('mu1').textContent = $('mu2').textContent = '—';
    $('mu-max').textContent = doc.growth_per_period.toPrecision(12);
    $('growth').textContent = Math.log(doc.growth_per_period).toPrecision(12);
    $('mu-bound').textContent = say('static_note');
    showNotes('mu-notes', []);
    showNotes('edge-notes', []);
    setState('readout', '');
    status('point-status', '');
  }

  // ---------------------------------------------------------------- presets and wiring
  function fillPresets() {
    const sel = $('preset'), keep = sel.value;
    sel.innerHTML = '';
    const blank = document.createElement('option');
    blank.value = ''; blank.textContent = '—';
    if (!STATIC) sel.appendChild(blank);
    presets.forEach((p) => {
      const o = document.createElement('option');
      o.value = p.id; o.textContent = p[lang] || p.en;
      sel.appendChild(o);
    });
    sel.value = keep;
  }
  async function applyPreset(id) {
    const p = presets.find((x) => x.id === id);
    if (!p) return;
    const c = p.chart;
    $('system').value = c.system || 'pendulum';
    $('duty').value = c.duty || '1/2';
    $('Q').value = c.Q || '';
    $('damping').value = c.damping || 'exact';
    $('modulation').value = 'square';
    $('max-order').value = c.max_order || 6;
    $('max-order-out').textContent = $('max-order').value;
    updateNote();
    outdated();
    await loadChart();
    await examine(p.point.T, p.point.m);
  }
  function onClick(ev) {
    const canvas = $('chart'), rect = canvas.getBoundingClientRect();
    const px = (ev.clientX - rect.left) * size.W / rect.width;
    const py = (ev.clientY - rect.top) * size.H / rect.height;
    const P = xy(), T = P.T(px), m = P.m(py);
    if (T < view.tmin || T > view.tmax || m < view.mmin || m > view.mmax) return;
    examine(decimal(T, 4), decimal(m, 4));
  }
  function onHover(ev) {
    const canvas = $('chart'), rect = canvas.getBoundingClientRect();
    const P = xy();
    const T = P.T((ev.clientX - rect.left) * size.W / rect.width);
    const m = P.m((ev.clientY - rect.top) * size.H / rect.height);
    $('hover').textContent = (T >= view.tmin && T <= view.tmax && m >= view.mmin && m <= view.mmax) ? `T/T0 = ${T.toFixed(4)}, m = ${m.toFixed(4)}` : '';
  }
  let timer = null;
  function changed() {
    updateNote();
    $('max-order-out').textContent = $('max-order').value;
    outdated();
    clearTimeout(timer);
    timer = setTimeout(async () => {
      await loadChart();
      if (point) await examine($('point').dataset.t, $('point').dataset.m);
    }, 150);
  }
  async function init() {
    drawColorbar();
    document.querySelectorAll('.lang button').forEach((b) => b.addEventListener('click', () => {
      lang = b.dataset.lang; applyLanguage(); drawChart();
    }));
    controls.forEach((id) => $(id).addEventListener(id === 'max-order' ? 'input' : 'change', changed));
    $('preset').addEventListener('change', () => applyPreset($('preset').value));
    $('chart').addEventListener('click', onClick);
    $('chart').addEventListener('mousemove', onHover);
    // drawn in CSS pixels: a new size is a new drawing
    let resized = false;
    const again = new ResizeObserver(() => {
      if (resized) return;
      resized = true;
      requestAnimationFrame(() => { resized = false; drawChart(); drawColorbar(); });
    });
    again.observe($('chart'));
    again.observe($('colorbar'));
    if (STATIC) controls.forEach((id) => { if (id !== 'amplitude') $(id).disabled = true; });
    try {
      presets = (await getJSON(STATIC ? 'data/presets.json' : 'api/presets')).presets;
    } catch (e) { presets = []; }
    applyLanguage();
    drawChart();
    $('point').textContent = say('click');
    if (STATIC && presets.length) { $('preset').value = presets[0].id; }
    await loadChart();
    requestAnimationFrame(animate);
  }
  // where (T, m) is drawn, in the pixels of the chart's canvas (its width and height attributes)
  const pixelOf = (T, m) => {
    const P = xy(), c = $('chart');
    return [P.x(T) * c.width / size.W, P.y(m) * c.height / size.H];
  };
  window.paramresApp = { stateAt, examine, loadChart, pixelOf, get run() { return run; }, get chart() { return chart; }, clientRun };
  init();
})();
