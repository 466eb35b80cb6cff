#include "report/html_page.hpp"

#include <nlohmann/json.hpp>

#include "report/markup.hpp"
#include "report/report_assets.hpp"

namespace sfcv::report {

std::string html_page_head(const std::string& title) {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
         html_escape(title) + "</title>\n<style>\n" + std::string(report_style()) +
         "</style>\n</head>\n<body>\n";
}

std::string html_page_nav(const std::vector<std::pair<std::string, std::string>>& sections) {
  std::string out = "<nav class=\"sections\" aria-label=\"sections\">";
  for (const auto& [id, label] : sections)
    out += "<a href=\"#" + html_escape(id) + "\">" + html_escape(label) + "</a>";
  return out + "</nav>\n";
}

std::string html_verdict(const std::string& verdict) {
  std::string cls = verdict;
  for (auto& c : cls)
    if (c == ' ' || c == '/') c = '-';
  return "<span class=\"verdict " + html_escape(cls) + "\">" + html_escape(verdict) + "</span>";
}

std::string json_text(const nlohmann::json& object, const char* key) {
  return object.contains(key) && object[key].is_string() ? object[key].get<std::string>()
                                                         : std::string();
}

std::string html_pictures_script() {
  // After the page's own script: the player is then shown, so the pictures' boxes have their
  // final widths. A ResizeObserver redoes the choice when a box's width changes (a window
  // resized, a phone turned).
  return R"js(<script>
(function () {
  "use strict";
  const MIN_TEXT_PX = 9;
  ["chart-svg", "situations-svg"].forEach((id) => {
    const box = document.getElementById(id);
    if (!box) return;
    let toggled = false, width = -1;
    box.addEventListener("click", () => { toggled = true; box.classList.toggle("fit"); });
    const readable = () => {
      if (toggled) return;
      box.classList.add("fit");
      let min = Infinity;
      box.querySelectorAll("svg text").forEach((t) => {
        const h = t.getBoundingClientRect().height;
        if (h > 0) min = Math.min(min, h);
      });
      if (min >= MIN_TEXT_PX) return;
      box.classList.remove("fit");
      // Natural size: show the highlighted nodes in the box.
      const node = box.querySelector("g.active, g.fired");
      if (!node) return;
      const r = node.getBoundingClientRect(), b = box.getBoundingClientRect();
      box.scrollLeft += r.left - b.left - (b.width - r.width) / 2;
      box.scrollTop += r.top - b.top - (b.height - r.height) / 2;
    };
    const check = () => {
      if (box.clientWidth === width) return;
      width = box.clientWidth;
      readable();
    };
    check();
    if (window.ResizeObserver) new ResizeObserver(check).observe(box);
  });
})();
</script>
)js";
}

std::string html_layout_probe() {
  // Runs last, after the page's own script built the player. Elements wider than the viewport
  // count only when no ancestor scrolls them in its own box.
  return R"js(<script>
(function () {
  "use strict";
  if (!/(^#|&)test(&|=|$)/.test(location.hash)) return;
  const doc = document.documentElement;
  const vw = doc.clientWidth;
  const box = (el) => { const b = el.getBoundingClientRect(); return { left: Math.round(b.left), top: Math.round(b.top + scrollY), width: Math.round(b.width), height: Math.round(b.height) }; };
  const scrolls = (el) => { for (let p = el.parentElement; p; p = p.parentElement) { const o = getComputedStyle(p).overflowX; if (o === "auto" || o === "scroll" || o === "hidden") return true; } return false; };
  const out = { viewport: vw, page: Math.max(doc.scrollWidth, document.body.scrollWidth), sticking_out: [], small_targets: [] };
  document.querySelectorAll("body *").forEach((el) => {
    const b = el.getBoundingClientRect();
    if (b.width > 0 && b.right > vw + 1 && !scrolls(el) && out.sticking_out.length < 10)
      out.sticking_out.push(el.tagName.toLowerCase() + (el.id ? "#" + el.id : "") + (el.className && typeof el.className === "string" ? "." + el.className.split(" ").join(".") : ""));
  });
  document.querySelectorAll("button, select, a.play, nav a").forEach((el) => {
    const b = el.getBoundingClientRect();
    if (b.width > 0 && Math.min(b.width, b.height) < (vw <= 600 ? 40 : 20)) out.small_targets.push(el.id || el.textContent.trim());
  });
  const chart = document.querySelector("#chart-svg svg");
  if (chart) {
    let min = 1e9;
    chart.querySelectorAll("text").forEach((t) => { const h = t.getBoundingClientRect().height; if (h > 0) min = Math.min(min, h); });
    out.chart = Object.assign(box(chart), { box: box(chart.parentElement), min_text: Math.round(min * 10) / 10, fit: chart.parentElement.classList.contains("fit") });
  }
  const player = document.getElementById("player");
  if (player && !player.hidden) {
    out.player = box(player);
    out.plays = Array.from(document.querySelectorAll("a.play")).map((a) => Number(a.dataset.property));
    out.traces = Array.from(document.querySelectorAll("#trace-select option")).map((o) => o.textContent);
    const wave = document.getElementById("waveform");
    out.waveform = Object.assign(box(wave), { columns: wave.querySelectorAll("rect.hit").length });
  }
  doc.dataset.sfcvLayout = JSON.stringify(out);
  if (window.parent !== window) window.parent.postMessage(JSON.stringify(out), "*");
})();
</script>
)js";
}

}  // namespace sfcv::report
