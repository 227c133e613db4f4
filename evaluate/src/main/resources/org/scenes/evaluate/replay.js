// Draws the frames of a game on a canvas: pitch, players in their team's colour (body direction,
// number), ball, the player with the ball ringed, score, play mode; a cycle slider and play/pause.
// Numbers of players on the same spot are set side by side, each tied to its player by a line.
// One player per .replay element, data in its JSON script.
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
    var owner = decode(data.owner, count, 1);
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

    // dark text on a light team colour, white on a dark one
    function textOn(colour) {
      var r = parseInt(colour.substr(1, 2), 16), g = parseInt(colour.substr(3, 2), 16), b = parseInt(colour.substr(5, 2), 16);
      return 0.299 * r + 0.587 * g + 0.114 * b > 140 ? "#000000" : "#ffffff";
    }

    function colourOf(i) {
      return data.colours[data.players[i][0] === "l" ? 0 : 1];
    }

    function nameOf(i) {
      return (data.players[i][0] === "l" ? data.left : data.right) + " " + data.players[i][1];
    }

    // Each number in a box above its player; a box that would cover one already placed moves
    // right (then up) until it is clear, and a line ties it to its player.
    function labels(index, holder) {
      var placed = [];
      var height = Math.round(1.8 * scale);
      context.font = "bold " + Math.round(1.5 * scale) + "px sans-serif";
      context.textAlign = "center";
      context.textBaseline = "middle";
      for (var i = 0; i < data.players.length; i++) {
        var px = sx(tracks[i][0][index]), py = sy(tracks[i][1][index]);
        var text = String(data.players[i][1]);
        var width = context.measureText(text).width + 0.5 * scale;
        var x = px, y = py - 2.2 * scale;
        for (var tries = 0; tries < 40 && clash(placed, x, y, width, height); tries++) {
          x += width + 2;
          if (tries % 4 === 3) {
            x = px;
            y -= height + 2;
          }
        }
        placed.push({x: x, y: y, width: width});
        if (x !== px || y !== py - 2.2 * scale) {
          context.strokeStyle = "#111111";
          context.lineWidth = 1;
          context.beginPath();
          context.moveTo(px, py);
          context.lineTo(x, y + height / 2);
          context.stroke();
        }
        context.fillStyle = colourOf(i);
        context.fillRect(x - width / 2, y - height / 2, width, height);
        // the number of the player with the ball in a white frame, like its ring
        context.strokeStyle = i === holder ? "#ffffff" : "#111111";
        context.lineWidth = i === holder ? 2 : 1;
        context.strokeRect(x - width / 2, y - height / 2, width, height);
        context.fillStyle = textOn(colourOf(i));
        context.fillText(text, x, y + 1);
      }
    }

    function clash(placed, x, y, width, height) {
      for (var k = 0; k < placed.length; k++) {
        if (Math.abs(placed[k].x - x) < (placed[k].width + width) / 2 + 1 && Math.abs(placed[k].y - y) < height + 1) {
          return true;
        }
      }
      return false;
    }

    function draw(index) {
      var event = data.events[eventOf[index]];
      var holder = owner[index] - 1;
      pitch();
      for (var i = 0; i < data.players.length; i++) {
        var x = tracks[i][0][index], y = tracks[i][1][index], body = tracks[i][2][index] * Math.PI / 180;
        context.fillStyle = colourOf(i);
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
      }
      if (holder >= 0) {
        context.strokeStyle = "#ffffff";
        context.lineWidth = 3;
        context.beginPath();
        context.arc(sx(tracks[holder][0][index]), sy(tracks[holder][1][index]), 1.5 * scale, 0, 2 * Math.PI);
        context.stroke();
      }
      context.fillStyle = "#ffffff";
      context.strokeStyle = "#000000";
      context.lineWidth = 1;
      context.beginPath();
      context.arc(sx(ballX[index]), sy(ballY[index]), 0.55 * scale, 0, 2 * Math.PI);
      context.fill();
      context.stroke();
      labels(index, holder);
      status.textContent = "cycle " + time[index] + " \u00b7 " + data.modes[event[1]] + " \u00b7 "
          + data.left + " " + event[2] + " : " + event[3] + " " + data.right
          + " \u00b7 ball " + ballX[index].toFixed(1) + " " + ballY[index].toFixed(1)
          + (holder >= 0 ? " with " + nameOf(holder) : " loose");
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
