// Draws the frames of a game on a canvas: pitch, players (body direction, number), ball, score,
// play mode; a cycle slider and play/pause. One player per .replay element, data in its JSON script.
(function () {
  "use strict";
  var PITCH_X = 52.5, PITCH_Y = 34, MARGIN = 5, GOAL = 7.01;
  // Each track is written step by step: one character of STEPS for a step of -30 to 30, or
  // "~STEP;" (ReplayPage.data writes them).
  var STEPS = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxy", RANGE = 30;

  function decode(text, count, scale) {
    var values = new Float64Array(count), value = 0, n = 0, i = 0;
    while (i < text.length && n < count) {
      var c = text.charAt(i);
      if (c === "~") {
        var end = text.indexOf(";", i);
        value += Number(text.substring(i + 1, end));
        i = end + 1;
      } else {
        value += STEPS.indexOf(c) - RANGE;
        i++;
      }
      values[n++] = value * scale;
    }
    return values;
  }

  function setup(root) {
    var data = JSON.parse(root.querySelector("script.replay-data").textContent);
    var count = data.frames;
    var time = decode(data.time, count, 1);
    var ballX = decode(data.ball[0], count, 0.1), ballY = decode(data.ball[1], count, 0.1);
    var tracks = data.tracks.map(function (t) {
      return [decode(t[0], count, 0.1), decode(t[1], count, 0.1), decode(t[2], count, 1)];
    });
    // the play mode and score of every frame, from the frames where they change
    var eventOf = new Int32Array(count);
    for (var e = 0; e < data.events.length; e++) {
      var until = e + 1 < data.events.length ? data.events[e + 1][0] : count;
      for (var f = data.events[e][0]; f < until; f++) {
        eventOf[f] = e;
      }
    }
    var canvas = root.querySelector("canvas");
    var slider = root.querySelector("input.replay-cycle");
    var button = root.querySelector("button.replay-play");
    var speed = root.querySelector("select.replay-speed");
    var status = root.querySelector(".replay-status");
    var context = canvas.getContext("2d");
    var scale = canvas.width / (2 * (PITCH_X + MARGIN));
    var timer = null;
    slider.max = String(count - 1);

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
      var event = data.events[eventOf[index]];
      pitch();
      for (var i = 0; i < data.players.length; i++) {
        var x = tracks[i][0][index], y = tracks[i][1][index], body = tracks[i][2][index] * Math.PI / 180;
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
      context.arc(sx(ballX[index]), sy(ballY[index]), 0.55 * scale, 0, 2 * Math.PI);
      context.fill();
      context.stroke();
      status.textContent = "cycle " + time[index] + " \u00b7 " + data.modes[event[1]] + " \u00b7 "
          + data.left + " " + event[2] + " : " + event[3] + " " + data.right
          + " \u00b7 ball " + ballX[index].toFixed(1) + " " + ballY[index].toFixed(1);
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
        if (next >= count) {
          draw(count - 1);
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
