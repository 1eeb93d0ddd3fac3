// The search-tree page of `ropras run --dump-tree DIR` (scenarios/common/tree/tree.js): draws the treeToJson()
// document inlined in #ropras-data as a collapsible tree. Belief nodes alternate with action nodes; the children
// of a node are built when it is first opened, so a tree of many thousand nodes opens at once. #ropras-stats
// reports what the page holds and draws (the browser test reads it): data-beliefs, data-actions (the document's
// counts), data-reachable (nodes reached from the root through the children lists), data-drawn (node rows in
// the page now), data-state ("ready" once drawn) and data-errors. URL hash: #expand-all or #level=N.
(function () {
  "use strict";
  var tree = JSON.parse(document.getElementById("ropras-data").textContent);
  var beliefs = tree.beliefs || [];
  var actions = tree.actions || [];
  var stats = document.getElementById("ropras-stats");
  var container = document.getElementById("ropras-tree");
  var minVisits = 0;

  function fixed(x, digits) {
    return typeof x === "number" && isFinite(x) ? x.toFixed(digits) : String(x);
  }

  function field(name, value, title) {
    var span = document.createElement("span");
    span.className = "field";
    if (title) span.title = title;
    span.appendChild(document.createTextNode(name + " "));
    var b = document.createElement("b");
    b.textContent = value;
    span.appendChild(b);
    return span;
  }

  function bar(share) {
    var span = document.createElement("span");
    span.className = "bar";
    span.style.width = Math.max(1, Math.round(60 * Math.min(1, Math.max(0, share)))) + "px";
    span.title = (100 * share).toFixed(1) + " % of the parent's visits";
    return span;
  }

  // children of a node as [kind, index] pairs, most visited first
  function childrenOf(kind, i) {
    var list = kind === "belief" ? beliefs[i].actions || [] : actions[i].children || [];
    var childKind = kind === "belief" ? "action" : "belief";
    var table = childKind === "belief" ? beliefs : actions;
    return list.slice().sort(function (a, b) { return table[b].visits - table[a].visits; })
      .map(function (c) { return [childKind, c]; });
  }

  function parentVisits(kind, i) {
    if (kind === "action") return beliefs[actions[i].parent].visits;
    var p = beliefs[i].parent;
    return p === null || p === undefined ? beliefs[i].visits : actions[p].visits;
  }

  function row(kind, i) {
    var div = document.createElement("div");
    div.className = "row";
    var toggle = document.createElement("span");
    toggle.className = "toggle";
    div.appendChild(toggle);
    var label = document.createElement("span");
    label.className = "label";
    var total = parentVisits(kind, i);
    if (kind === "belief") {
      var b = beliefs[i];
      label.textContent = (b.parent === null || b.parent === undefined ? "root b" : "b") + i;
      div.appendChild(label);
      div.appendChild(bar(total > 0 ? b.visits / total : 1));
      div.appendChild(field("N", String(b.visits), "visits"));
      div.appendChild(field("V", fixed(b.value, 2), "value of the belief node"));
      div.appendChild(field("particles", String(b.particles)));
      div.appendChild(field("depth", String(b.depth), "macro levels below the root"));
      div.appendChild(field("steps", String(b.steps), "primitive steps from the root"));
      var key = document.createElement("span");
      key.className = "key";
      key.title = "macro observation key (the bin of the observation sequence)";
      key.textContent = b.parent === null || b.parent === undefined ? "" : "obs " + b.key;
      div.appendChild(key);
    } else {
      var a = actions[i];
      label.textContent = "a" + i;
      div.appendChild(label);
      div.appendChild(bar(total > 0 ? a.visits / total : 0));
      div.appendChild(field("N", String(a.visits), "visits"));
      div.appendChild(field("Q", fixed(a.q, 2)));
      div.appendChild(field("\u03c0*", fixed(a.pi_star, 3), "pi*(a|b) over the siblings"));
      var macro = document.createElement("span");
      macro.className = "macro";
      macro.title = "the macro-action in brief";
      macro.textContent = a.macro;
      div.appendChild(macro);
    }
    return div;
  }

  function visible(kind, i) {
    return (kind === "belief" ? beliefs[i].visits : actions[i].visits) >= minVisits;
  }

  function makeNode(kind, i) {
    var li = document.createElement("li");
    li.className = "node " + kind;
    li.dataset.kind = kind;
    li.dataset.index = String(i);
    var r = row(kind, i);
    li.appendChild(r);
    var kids = childrenOf(kind, i);
    var toggle = r.firstChild;
    if (kids.length === 0) {
      li.classList.add("leaf");
      toggle.textContent = "\u00b7";
    } else {
      toggle.textContent = "\u25b8";
      toggle.title = kids.length + " children";
      toggle.addEventListener("click", function () { setOpen(li, !li.classList.contains("open")); report(); });
    }
    return li;
  }

  function setOpen(li, open) {
    var toggle = li.firstChild.firstChild;
    if (li.classList.contains("leaf")) return;
    if (open && !li.querySelector(":scope > ul")) {
      var ul = document.createElement("ul");
      ul.className = "children";
      childrenOf(li.dataset.kind, Number(li.dataset.index)).forEach(function (c) {
        if (visible(c[0], c[1])) ul.appendChild(makeNode(c[0], c[1]));
      });
      li.appendChild(ul);
    }
    var list = li.querySelector(":scope > ul");
    if (list) list.style.display = open ? "" : "none";
    li.classList.toggle("open", open);
    toggle.textContent = open ? "\u25be" : "\u25b8";
  }

  // opens every node down to macro level `level` (level < 0: everything), closes the rest
  function openTo(level) {
    var stack = [[container.querySelector("li.node"), 0]];
    while (stack.length) {
      var top = stack.pop();
      var li = top[0], beliefLevel = top[1];
      // a belief at macro level d and its actions are open iff d < level
      var open = level < 0 || beliefLevel < level;
      if (!open) {
        if (li.classList.contains("open")) setOpen(li, false);
        continue;
      }
      setOpen(li, true);
      var ul = li.querySelector(":scope > ul");
      if (!ul) continue;
      for (var k = 0; k < ul.children.length; ++k) {
        var child = ul.children[k];
        stack.push([child, child.dataset.kind === "belief" ? beliefLevel + 1 : beliefLevel]);
      }
    }
  }

  function reachable() {
    if (beliefs.length === 0) return 0;
    var count = 0, stack = [["belief", 0]], seen = { belief: {}, action: {} };
    while (stack.length) {
      var n = stack.pop();
      if (seen[n[0]][n[1]]) continue;
      seen[n[0]][n[1]] = true;
      ++count;
      childrenOf(n[0], n[1]).forEach(function (c) { stack.push(c); });
    }
    return count;
  }

  function report() {
    var drawn = container.querySelectorAll("li.node").length;
    stats.setAttribute("data-drawn", String(drawn));
    document.getElementById("ropras-drawn").textContent = drawn + " of " + (beliefs.length + actions.length) +
      " nodes drawn";
  }

  function levelsTable() {
    var table = document.getElementById("ropras-levels");
    var levels = tree.levels || [];
    if (levels.length === 0) return;
    var head = ["level", "beliefs", "visited \u2264 1", "actions / belief", "obs. children / action",
      "particles / belief", "steps"];
    var tr = document.createElement("tr");
    head.forEach(function (h) { var th = document.createElement("th"); th.textContent = h; tr.appendChild(th); });
    table.appendChild(tr);
    levels.forEach(function (l, d) {
      var cells = [d, l.beliefs, fixed(l.visited_once_share, 2), fixed(l.actions_per_belief, 2),
        fixed(l.observations_per_action, 2), fixed(l.particles_per_belief, 1), l.min_steps + "\u2013" + l.max_steps];
      var r = document.createElement("tr");
      cells.forEach(function (c) { var td = document.createElement("td"); td.textContent = String(c); r.appendChild(td); });
      table.appendChild(r);
    });
  }

  document.getElementById("ropras-title").textContent = "search tree: " + tree.solver + ", planning call " +
    tree.plan + " (step " + tree.step + ")";
  document.title = "ropras tree " + tree.solver + " plan " + tree.plan;
  document.getElementById("ropras-summary").textContent = tree.simulations + " simulations, " + beliefs.length +
    " belief nodes, " + actions.length + " action nodes, " + fixed(tree.reference_per_simulation, 2) +
    " reference plans per simulation";
  levelsTable();
  stats.setAttribute("data-beliefs", String(beliefs.length));
  stats.setAttribute("data-actions", String(actions.length));
  stats.setAttribute("data-simulations", String(tree.simulations));
  stats.setAttribute("data-reachable", String(reachable()));
  var top = document.createElement("ul");
  top.className = "children";
  if (beliefs.length > 0) top.appendChild(makeNode("belief", 0));
  container.appendChild(top);

  var levelInput = document.getElementById("ropras-level");
  var hash = window.location.hash;
  var match = /level=(\d+)/.exec(hash);
  if (hash === "#expand-all") levelInput.value = String(beliefs.length);
  else if (match) levelInput.value = match[1];
  if (beliefs.length > 0) openTo(hash === "#expand-all" ? -1 : Number(levelInput.value));

  function redraw() {
    if (beliefs.length === 0) return;
    top.textContent = "";
    top.appendChild(makeNode("belief", 0));
    openTo(Number(levelInput.value));
    report();
  }
  document.getElementById("ropras-expand").addEventListener("click", function () {
    if (beliefs.length > 0) openTo(-1);
    report();
  });
  document.getElementById("ropras-collapse").addEventListener("click", function () {
    if (beliefs.length > 0) openTo(0);
    report();
  });
  levelInput.addEventListener("change", redraw);
  document.getElementById("ropras-min-visits").addEventListener("change", function (e) {
    minVisits = Math.max(0, Number(e.target.value) || 0);
    redraw();
  });
  report();
  stats.setAttribute("data-state", "ready");
})();
