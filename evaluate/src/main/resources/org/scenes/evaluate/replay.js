// Draws the frames of a game on a canvas: pitch, players (body direction, number), ball, score,
// play mode; a cycle slider and play/pause. One player per .replay element, data in its JSON script.
(function () {
  "use strict";
  var PITCH_X = 52.5, PITCH_Y = 34, MARGIN = 5, GOAL = 7.01;

  function setup(root) {
    var data = JSON.parse(root.querySelector("script.replay-data").textContent);
    var canvas = root.querySelector("canvas");
    var slider = root.querySelector("input.replay-cycle");
    var button = root.querySelector("button.replay-play");
    var speed = root.querySelector("select.replay-speed");
    var status = root.querySelector(".replay-status");
    var context = canvas.getContext("2d");
    var scale = canvas.width / (2 * (PITCH_X + MARGIN));
    var timer = null;
    slider.max = String(data.frames.length - 1);

    function sx(x) { return (x + PITCH_X + MARGIN) * scale; }
    function sy(y) { return (y + PITCH_Y + MARGIN) * scale; }

    function pitch() {
      context.fillStyle = "#3a7d3a";
      context.fillRect(0, 0, canvas.width, canvas.height);
      context.strokeStyle = "#ffffff";
      context.lineWidth = 1.5;
      context.strokeRect(sx(-PITCH_X), sy(-PITCH_Y), 2 * PITCH_X * scale, 2 * PITCH_Y * scale);
      context.beginPath();
      context.moveTo(sx(0), sy(-PITCH_Y));
      context.lineTo(sx(0), sy(PITCH_Y));
      context.stroke();
      context.beginPath();
      context.arc(sx(0), sy(0), 9.15 * scale, 0, 2 * Math.PI);
      context.stroke();
      [-1, 1].forEach(function (side) {
        var line = side * PITCH_X;
        context.strokeRect(Math.min(sx(line), sx(line - side * 16.5)), sy(-20.16), 16.5 * scale, 40.32 * scale);
        context.strokeRect(Math.min(sx(line), sx(line - side * 5.5)), sy(-9.16), 5.5 * scale, 18.32 * scale);
        context.fillStyle = "#dddddd";
        context.fillRect(Math.min(sx(line), sx(line + side * 2)), sy(-GOAL), 2 * scale, 2 * GOAL * scale);
      });
    }

    function draw(index) {
      var frame = data.frames[index];
      pitch();
      var players = frame[6];
      for (var i = 0; i < data.players.length; i++) {
        var x = players[3 * i], y = players[3 * i + 1], body = players[3 * i + 2] * Math.PI / 180;
        var left = data.players[i][0] === "l";
        context.fillStyle = left ? "#f2c200" : "#2f6fd6";
        context.beginPath();
        context.arc(sx(x), sy(y), 0.9 * scale, 0, 2 * Math.PI);
        context.fill();
        context.strokeStyle = "#111111";
        context.lineWidth = 1;
        context.stroke();
        context.beginPath();
        context.moveTo(sx(x), sy(y));
        context.lineTo(sx(x + 1.6 * Math.cos(body)), sy(y + 1.6 * Math.sin(body)));
        context.stroke();
        context.fillStyle = "#000000";
        context.font = Math.round(1.1 * scale) + "px sans-serif";
        context.textAlign = "center";
        context.textBaseline = "middle";
        context.fillText(String(data.players[i][1]), sx(x), sy(y - 1.8));
      }
      context.fillStyle = "#ffffff";
      context.strokeStyle = "#000000";
      context.beginPath();
      context.arc(sx(frame[4]), sy(frame[5]), 0.55 * scale, 0, 2 * Math.PI);
      context.fill();
      context.stroke();
      status.textContent = "cycle " + frame[0] + " \u00b7 " + data.modes[frame[1]] + " \u00b7 "
          + data.left + " " + frame[2] + " : " + frame[3] + " " + data.right;
      slider.value = String(index);
    }

    function stop() {
      if (timer !== null) {
        clearInterval(timer);
        timer = null;
      }
      button.textContent = "\u25b6 play";
    }

    button.addEventListener("click", function () {
      if (timer !== null) {
        stop();
        return;
      }
      button.textContent = "\u275a\u275a pause";
      timer = setInterval(function () {
        var next = Number(slider.value) + Number(speed.value);
        if (next >= data.frames.length) {
          draw(data.frames.length - 1);
          stop();
        } else {
          draw(next);
        }
      }, 100);
    });
    slider.addEventListener("input", function () { draw(Number(slider.value)); });
    draw(0);
    root.setAttribute("data-ready", "true");
  }

  var roots = document.querySelectorAll(".replay");
  for (var i = 0; i < roots.length; i++) {
    setup(roots[i]);
  }
})();
