// resvg's side of bench/bench_svg.c: node bench_svg_resvg.js LIST SIZE RUNS
// Reads the files LIST names into memory, then parses and renders each
// SIZE px wide, RUNS times, and prints the median processor seconds of a run.
const { Resvg } = require(process.env.CG_RESVG_MODULE || '@resvg/resvg-js');
const fs = require('fs');
const files = fs.readFileSync(process.argv[2], 'utf8').split('\n').filter((f) => f.length > 0);
const size = parseInt(process.argv[3]);
const runs = parseInt(process.argv[4] || '3');
const data = files.map((f) => fs.readFileSync(f));
const times = [];
for (let r = 0; r < runs; r++) {
  const start = process.cpuUsage();
  for (const svg of data) {
    try {
      const image = new Resvg(svg, { fitTo: { mode: 'width', value: size }, font: { loadSystemFonts: false } }).render();
      if (image.width === 0) throw new Error('empty');
    } catch (e) {
      // counted in the time like any other icon
    }
  }
  const used = process.cpuUsage(start);
  times.push((used.user + used.system) / 1e6);
}
times.sort((a, b) => a - b);
console.log(times[Math.floor(times.length / 2)]);
