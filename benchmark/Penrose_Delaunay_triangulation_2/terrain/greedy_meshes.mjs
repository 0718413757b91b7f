// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Meshes a height grid with delatin (greedy insertion, Garland-Heckbert) and
// @mapbox/martini (RTIN), for terrain_benchmark.sh.
//
//   node greedy_meshes.mjs delatin HEIGHTS.f64 WIDTH HEIGHT OUT_PREFIX vertices N...
//   node greedy_meshes.mjs delatin HEIGHTS.f64 WIDTH HEIGHT OUT_PREFIX error E...
//   node greedy_meshes.mjs martini HEIGHTS.f64 WIDTH HEIGHT OUT_PREFIX vertices N...
//
// HEIGHTS.f64: WIDTH x HEIGHT little-endian doubles, row 0 first (the top).
// Writes OUT_PREFIX_TOOL_<N|E>.off, vertices (column, row, height) on the
// grid's nodes: delatin refined to N vertices or to the maximum error E;
// martini at the error whose mesh has at most N vertices, the most of those
// (martini needs a 2^k + 1 grid: the
// grid is padded by repeating its last row and column, and the padding's
// triangles are kept, so that every node of the grid is covered). Prints one
// CSV line a mesh: tool,target,vertices,triangles,seconds.
import {readFileSync, writeFileSync} from 'fs';
import {createRequire} from 'module';
const require = createRequire(import.meta.url);
const Delatin = (await import(require.resolve('delatin'))).default;
const Martini = (await import(require.resolve('@mapbox/martini'))).default;

const [tool, file, w, h, prefix, mode, ...targets] = process.argv.slice(2);
const width = Number(w), height = Number(h);
const bytes = readFileSync(file);
const heights = new Float64Array(bytes.buffer, bytes.byteOffset, width * height);

function writeOff(name, coords, triangles, z) {
    const n = coords.length / 2, m = triangles.length / 3;
    const lines = ['OFF', `${n} ${m} 0`];
    for (let i = 0; i < n; i++) lines.push(`${coords[2 * i]} ${coords[2 * i + 1]} ${z(coords[2 * i], coords[2 * i + 1])}`);
    for (let t = 0; t < m; t++) lines.push(`3 ${triangles[3 * t]} ${triangles[3 * t + 1]} ${triangles[3 * t + 2]}`);
    writeFileSync(name, lines.join('\n') + '\n');
}
const at = (x, y) => heights[y * width + x];

for (const target of tool === 'delatin' ? targets.map(Number) : []) {
    const start = process.hrtime.bigint();
    const tin = new Delatin(heights, width, height);
    if (mode === 'vertices') {
        while (tin.coords.length / 2 < target && tin.getMaxError() > 0) tin.refine();
    } else {
        tin.run(target);
    }
    const seconds = Number(process.hrtime.bigint() - start) / 1e9;
    writeOff(`${prefix}_delatin_${target}.off`, tin.coords, tin.triangles, at);
    console.log(`delatin,${target},${tin.coords.length / 2},${tin.triangles.length / 3},${seconds}`);
}

if (tool === 'martini' && mode === 'vertices') {
    let size = 2;
    while (size + 1 < Math.max(width, height)) size *= 2;
    size += 1;
    const grid = new Float32Array(size * size);
    for (let y = 0; y < size; y++)
        for (let x = 0; x < size; x++) grid[y * size + x] = at(Math.min(x, width - 1), Math.min(y, height - 1));
    const start = process.hrtime.bigint();
    const tile = new Martini(size).createTile(grid);
    const setup = Number(process.hrtime.bigint() - start) / 1e9;
    for (const target of targets.map(Number)) {
        // the vertex count falls as the error grows: bisect on the error
        let lo = 0, hi = 1;
        while (tile.getMesh(hi).vertices.length / 2 > target) hi *= 2;
        for (let k = 0; k < 40; k++) {
            const mid = 0.5 * (lo + hi);
            if (tile.getMesh(mid).vertices.length / 2 > target) lo = mid; else hi = mid;
        }
        const t0 = process.hrtime.bigint();
        const mesh = tile.getMesh(hi);
        const seconds = setup + Number(process.hrtime.bigint() - t0) / 1e9;
        writeOff(`${prefix}_martini_${target}.off`, mesh.vertices, mesh.triangles,
                 (x, y) => grid[y * size + x]);
        console.log(`martini,${target},${mesh.vertices.length / 2},${mesh.triangles.length / 3},${seconds}`);
    }
}
