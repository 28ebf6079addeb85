/* Injected into a copy of a generated page by tests/html_check.sh. After
 * the page has loaded it appends one line to the DOM, which Chromium's
 * --dump-dom prints:
 *   IMAGES n BROKEN k srcs... UNLINKED u srcs... OVERLAPS o what... END
 * BROKEN: images that failed to load (a capturing 'error' listener, plus
 * naturalWidth 0 after 'load'); UNLINKED: images not inside a link (every
 * picture opens at full size on a click); OVERLAPS: pairs of text boxes
 * that intersect inside an inline SVG figure (or a text outside its
 * figure), and pairs of pictures and captions of the page that intersect,
 * as laid out by the browser. */
(function () {
  var broken = [];
  window.addEventListener("error", function (e) {
    if (e.target && e.target.tagName === "IMG") broken.push(e.target.getAttribute("src"));
  }, true);
  function hit(a, b) {
    return a.width > 0 && b.width > 0 && a.left < b.right - 0.5 && b.left < a.right - 0.5 &&
           a.top < b.bottom - 0.5 && b.top < a.bottom - 0.5;
  }
  function inside(a, b) {
    return a.left >= b.left - 0.5 && a.right <= b.right + 0.5 && a.top >= b.top - 0.5 &&
           a.bottom <= b.bottom + 0.5;
  }
  function name(el) {
    return el.tagName.toLowerCase() + "(" + (el.getAttribute("src") || el.textContent).slice(0, 40) + ")";
  }
  window.addEventListener("load", function () {
    var imgs = document.images, unlinked = [], over = [], i, j, k, l;
    for (i = 0; i < imgs.length; ++i) {
      var src = imgs[i].getAttribute("src"), a = imgs[i].closest("a");
      if (imgs[i].naturalWidth === 0 && broken.indexOf(src) < 0) broken.push(src);
      if (!a || !a.getAttribute("href")) unlinked.push(src);
    }
    var svgs = document.querySelectorAll("svg");
    for (i = 0; i < svgs.length; ++i) {
      var t = svgs[i].querySelectorAll("text"), box = svgs[i].getBoundingClientRect(), r = [];
      for (k = 0; k < t.length; ++k) r.push(t[k].getBoundingClientRect());
      for (k = 0; k < t.length; ++k) {
        if (!inside(r[k], box)) over.push("outside figure: " + t[k].textContent);
        for (l = k + 1; l < t.length; ++l)
          if (hit(r[k], r[l])) over.push(t[k].textContent + " / " + t[l].textContent);
      }
    }
    var els = document.querySelectorAll("figure img, figure > svg, figcaption");
    for (i = 0; i < els.length; ++i)
      for (j = i + 1; j < els.length; ++j)
        if (!els[i].contains(els[j]) && !els[j].contains(els[i]) &&
            hit(els[i].getBoundingClientRect(), els[j].getBoundingClientRect()))
          over.push(name(els[i]) + " / " + name(els[j]));
    var d = document.createElement("p");
    d.id = "pagecheck";
    d.textContent = "IMAGES " + imgs.length + " BROKEN " + broken.length + " " + broken.join(" ") +
                    " UNLINKED " + unlinked.length + " " + unlinked.join(" ") +
                    " OVERLAPS " + over.length + " " + over.join(" ; ") + " END";
    document.body.appendChild(d);
  });
})();
